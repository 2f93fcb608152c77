#!/usr/bin/env bash
# The HTML report as a reader sees it: `rotbeam suite --quick --no-studies` (the roll-up and the
# 45° bend, ~15 s) writes a report into OUT, and headless Chromium opens it (browser_check.py: no
# broken image or link, no console error, no literal Markdown in the rendered text, the summary and
# the contents first). The report and the screenshot of its first screen, OUT/first-screen.png,
# stay for a look. Usage: report_browser.sh ROTBEAM OUT
set -u
rotbeam=$1
out=$2
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$out"
mkdir -p "$out"
if ! "$rotbeam" suite --quick --no-studies --jobs 2 --out "$out" >"$out/suite.log" 2>&1; then
    echo "FAIL: suite --quick --no-studies exited non-zero: $(tail -3 "$out/suite.log")"
    exit 1
fi
# Debian's python3, whose python3-websockets drives Chromium (scripts/install-deps.sh installs
# both); a python3 earlier on PATH (a virtual environment) may not have it.
/usr/bin/python3 "$here/browser_check.py" "$out"
