# Checks of rotbeam output folders shared by the suite tests (docs/durability.md), sourced as
# `. results_check.sh ROTBEAM COMPARE_RESULTS_PY`: sets `rotbeam` and `compare`
# (scripts/compare-results.py), brings scratch.sh's set-up (work, fail, failures) and defines
# `same` and `complete_files`.
rotbeam=$1
compare=$2
. "$(dirname "${BASH_SOURCE[0]}")/scratch.sh"

same() {  # same DIR_A DIR_B WHAT: identical results by compare-results.py
    "$compare" "$1" "$2" >"$work/compare.txt" 2>&1 || {
        fail "$3 differs from the reference $(basename "$1"):"
        head -5 "$work/compare.txt"
    }
}

# complete_files DIR WHAT [temporaries-allowed]: no temporary (unless allowed: a process killed by
# SIGKILL cannot remove the one it was writing; the next suite in DIR clears it), every JSON
# parses, no empty file.
complete_files() {
    if [ "${3:-}" != temporaries-allowed ] && find "$1" -name '*.rotbeam-tmp.*' | grep -q .; then
        fail "$2: temporary left behind"
    fi
    python3 - "$1" <<'PY' || fail "$2: a truncated or empty JSON file"
import json, pathlib, sys
for p in pathlib.Path(sys.argv[1]).rglob("*.json"):
    json.loads(p.read_text())
PY
    if find "$1" -type f -empty | grep -q .; then fail "$2: an empty file"; fi
}
