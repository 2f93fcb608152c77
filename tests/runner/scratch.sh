# The set-up every runner check shares, sourced by it: a scratch folder `work`, removed on exit,
# and `fail`, which prints one line and counts it in `failures` (the check's exit status follows
# from that count).
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
