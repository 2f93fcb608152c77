#!/usr/bin/env bash
# The report is complete and consistent (docs/studies.md): `rotbeam suite --quick --jobs 2` (the
# whole quick suite with its studies, ~50 s of CPU, written once by the ctest fixture quick_suite
# into SUITE) wrote a report in which every linked file exists, every table's numbers parse and no
# result holds NaN or an absurd value (check_report.py says exactly what is checked). And a figure
# that cannot be drawn stops the study loudly, naming it, instead of leaving a link to nothing.
# Usage: report_complete.sh ROTBEAM SUITE
set -u
rotbeam=$1
suite=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

[ -f "$suite/index.md" ] || fail "no quick suite in $suite (the fixture quick_suite failed?)"
python3 "$here/check_report.py" "$suite" || fail "the report is incomplete or inconsistent"

# Without gnuplot the study stops with one message naming the figure, and writes no page.
PATH=/nonexistent "$rotbeam" study extremes --quick --out "$work/nognuplot" >"$work/out" 2>"$work/err"
rc=$?
[ $rc -ne 0 ] || fail "study extremes without gnuplot exited 0"
grep -q "gnuplot failed on reports/study_panels.gp for .*extremes-" "$work/err" ||
    fail "no message naming the figure: $(cat "$work/err")"
[ ! -e "$work/nognuplot/study-extremes.md" ] || fail "a page linking undrawn figures was written"

[ $failures -eq 0 ] && echo "report complete: all checks passed" || echo "report: $failures failures"
[ $failures -eq 0 ]
