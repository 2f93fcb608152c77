#!/usr/bin/env bash
# fuzz_command_line keeps its own copy of the commands' option tables (the program's live inside
# the command functions). This check fails when the copy drifts: for every command that
# `rotbeam --help` lists, the usage line, the required arguments and every option (its name, its
# value name or none, repeatable or not) in `rotbeam COMMAND --help` must equal those of the help
# the fuzz target prints from its copy (ROTBEAM_FUZZ_PRINT_TABLE=1); the summaries, the options'
# help texts and their order are not compared. Usage: command_table.sh ROTBEAM FUZZ_COMMAND_LINE
set -u
rotbeam=$1
fuzz=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

ROTBEAM_FUZZ_PRINT_TABLE=1 "$fuzz" >"$work/fuzz.txt" 2>"$work/fuzz.err" || {
    echo "FAIL: $fuzz did not print its table: $(head -3 "$work/fuzz.err")"
    exit 1
}
"$rotbeam" --help >"$work/commands.txt" || { echo "FAIL: rotbeam --help failed"; exit 1; }
for c in $(sed -n '/^commands:/,/^$/s/^  \([a-z][a-z-]*\) .*/\1/p' "$work/commands.txt"); do
    echo "=== $c" >>"$work/program.txt"
    "$rotbeam" "$c" --help >>"$work/program.txt" || { echo "FAIL: rotbeam $c --help failed"; exit 1; }
done
python3 - "$work/program.txt" "$work/fuzz.txt" <<'PY'
import re, sys

def commands(path):
    """{command: [usage line, argument lines..., '--option VALUE (repeatable)'...]}"""
    out, name, section = {}, None, None
    for line in open(path, encoding="utf-8"):
        line = line.rstrip("\n")
        if line.startswith("=== "):
            name, section = line[4:], None
            out[name] = []
        elif line.startswith("usage: "):
            out[name].append(line)
        elif line in ("arguments:", "options:"):
            section = line
        elif section == "arguments:" and line.startswith("  "):
            out[name].append("argument " + line.strip())
        elif section == "options:" and line.startswith("  --"):
            m = re.match(r"  --(\S+)(?: (\S+))?(?:\s{2,}|\s*$)", line)
            entry = "--" + m.group(1) + (" " + m.group(2) if m.group(2) else "")
            if line.endswith("(repeatable)") or "(repeatable) (default" in line:
                entry += " (repeatable)"
            out[name].append(entry)
    return out

program, fuzz = commands(sys.argv[1]), commands(sys.argv[2])
failures = 0
if not program:
    print("FAIL: rotbeam --help lists no command")
    failures += 1
for name in sorted(set(program) | set(fuzz)):
    if name not in fuzz:
        print(f"FAIL: fuzz_command_line has no table for `{name}`")
        failures += 1
    elif name not in program:
        print(f"FAIL: fuzz_command_line has a table for `{name}`, which rotbeam does not list")
        failures += 1
    elif sorted(program[name]) != sorted(fuzz[name]):
        only_program = sorted(set(program[name]) - set(fuzz[name]))
        only_fuzz = sorted(set(fuzz[name]) - set(program[name]))
        print(f"FAIL: `{name}`: only rotbeam has {only_program}, only fuzz_command_line {only_fuzz}")
        failures += 1
if failures:
    sys.exit(1)
print(f"fuzz_command_line's tables equal rotbeam's for {len(program)} commands")
PY
