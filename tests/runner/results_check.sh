# Checks of rotbeam output folders shared by the suite tests (docs/durability.md), sourced as
# `. results_check.sh ROTBEAM COMPARE_RESULTS_PY`: sets `rotbeam` and `compare`
# (scripts/compare-results.py), brings scratch.sh's set-up (work, fail, failures) and defines
# `same`, `complete_files`, `limited` and `full_disk`.
rotbeam=$1
compare=$2
. "$(dirname "${BASH_SOURCE[0]}")/scratch.sh"

# limited KIB ERR COMMAND...: COMMAND under a file size limit of KIB KiB (ulimit -f, the EFBIG of a
# full disk), its output discarded and its stderr written to ERR through a pipe (stderr into a file
# would be cut at the limit too, and the error line with it); returns COMMAND's exit status.
limited() {
    local kib=$1 err=$2
    shift 2
    (
        ulimit -f "$kib"
        exec "$@" 2>&1 >/dev/null
    ) | cat >"$err"
    return "${PIPESTATUS[0]}"
}

same() {  # same DIR_A DIR_B WHAT: identical results by compare-results.py
    "$compare" "$1" "$2" >"$work/compare.txt" 2>&1 || {
        fail "$3 differs from the reference $(basename "$1"):"
        head -5 "$work/compare.txt"
    }
}

# complete_files DIR WHAT [temporaries-allowed]: no temporary (unless allowed: a process killed by
# SIGKILL cannot remove the one it was writing; the next suite in DIR clears it), every JSON
# parses, no empty file, and no file cut short: every text file the program writes (JSON, CSV,
# gnuplot data, Markdown, HTML, SVG) ends with its last line's newline, every CSV row has the
# header's number of fields, every PNG ends with its IEND chunk, every SVG with its closing tag.
complete_files() {
    if [ "${3:-}" != temporaries-allowed ] && find "$1" -name '*.rotbeam-tmp.*' | grep -q .; then
        fail "$2: temporary left behind"
    fi
    python3 - "$1" <<'PY' || fail "$2: a truncated or empty file"
import csv, json, pathlib, sys
bad = []
for p in pathlib.Path(sys.argv[1]).rglob("*"):
    if not p.is_file() or ".rotbeam-tmp." in p.name:
        continue
    data = p.read_bytes()
    if p.suffix == ".json":
        try:
            json.loads(data)
        except ValueError as e:
            bad.append(f"{p}: {e}")
    if p.suffix in (".json", ".csv", ".dat", ".md", ".html", ".svg") and not data.endswith(b"\n"):
        bad.append(f"{p}: no newline at the end")
    if p.suffix == ".csv":
        rows = list(csv.reader(data.decode().splitlines()))
        if any(len(r) != len(rows[0]) for r in rows):
            bad.append(f"{p}: a row with another number of fields than the header")
    if p.suffix == ".png" and not data.endswith(b"IEND\xaeB`\x82"):
        bad.append(f"{p}: no IEND chunk at the end")
    if p.suffix == ".svg" and not data.rstrip().endswith(b"</svg>"):
        bad.append(f"{p}: no closing </svg> tag at the end")
for b in bad[:5]:
    print(b)
sys.exit(1 if bad else 0)
PY
    if find "$1" -type f -empty | grep -q .; then fail "$2: an empty file"; fi
}

# full_disk KIB DIR WHAT COMMAND...: COMMAND, which writes into DIR, under a file size limit of KIB
# KiB must exit 4 with its last line naming a file of DIR and the limit, and leave only complete
# files; sets `last` (that line) for the caller's further checks.
full_disk() {
    local kib=$1 dir=$2 what=$3 code
    shift 3
    limited "$kib" "$work/err.txt" "$@"
    code=$?
    last=$(tail -1 "$work/err.txt")
    [ $code -eq 4 ] || fail "$what under ulimit -f $kib: exit $code, expected 4: $last"
    grep -q "^rotbeam: $dir/.*: write failed, nothing written: file too large" <<<"$last" ||
        fail "$what under ulimit -f $kib: the last line does not name the file and the limit: $last"
    complete_files "$dir" "$what under ulimit -f $kib"
}
