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
# The convergence page's header naming an element order its study did not run (23: a valid order,
# not among those its JSON records) fails the check on a copy of the report.
cp -r "$suite" "$work/orders"
sed -i 's/(2 elements, orders [0-9]*/(2 elements, orders 23/' "$work/orders/study-convergence.md"
python3 "$here/check_report.py" "$work/orders" >"$work/out" &&
    fail "a header naming an order the study did not run passed the check"
grep -q "study-convergence.md: 'orders 23, .*element order 23 outside the orders the study ran" "$work/out" ||
    fail "no line naming the order the study did not run: $(head -3 "$work/out")"

# Without gnuplot the study stops with one message naming the figure, and writes no page.
PATH=/nonexistent "$rotbeam" study extremes --quick --out "$work/nognuplot" >"$work/out" 2>"$work/err"
rc=$?
[ $rc -ne 0 ] || fail "study extremes without gnuplot exited 0"
grep -q "gnuplot failed on reports/study_panels.gp for .*extremes-" "$work/err" ||
    fail "no message naming the figure: $(cat "$work/err")"
[ ! -e "$work/nognuplot/study-extremes.md" ] || fail "a page linking undrawn figures was written"

[ $failures -eq 0 ] && echo "report complete: all checks passed" || echo "report: $failures failures"
[ $failures -eq 0 ]
