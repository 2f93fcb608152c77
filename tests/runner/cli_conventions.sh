#!/usr/bin/env bash
# The conventions a user expects of the command line: --version names the dependencies' versions;
# every option of every command (as the completion script offers it, generated from the same
# tables the parser reads) is accepted by the parser and listed by the command's --help with its
# default; the completion script completes `rotbeam r` and `rotbeam run --fo`; every JSON result
# has the schema version, verify's table included. Usage: cli_conventions.sh ROTBEAM COMPLETION_SCRIPT
set -u
rotbeam=$1
script=$2
. "$(dirname "$0")/scratch.sh"

"$rotbeam" --version >"$work/version" || fail "--version: exit $?"
for dep in SUNDIALS Eigen GSL yaml-cpp SuiteSparse KLU Spectra Boost cmark-gfm; do
    grep -Eq "$dep[^0-9]*[0-9]+\.[0-9]+" "$work/version" || fail "--version names no $dep version"
done

# The installed script is the one the program prints.
"$rotbeam" completion bash | cmp -s - "$script" || fail "$script differs from 'rotbeam completion bash'"
. "$script"
# complete WORDS...: COMPREPLY for the last word, space-separated.
complete_words() {
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    COMPREPLY=()
    _rotbeam
    echo "${COMPREPLY[*]}"
}
[ "$(complete_words rotbeam r)" = "reference run" ] ||
    fail "rotbeam r completes to '$(complete_words rotbeam r)'"
[ "$(complete_words rotbeam run --fo)" = "--formulation" ] ||
    fail "rotbeam run --fo completes to '$(complete_words rotbeam run --fo)'"

commands=$(complete_words rotbeam "")
for command in $commands; do
    case $command in --*) continue ;; esac
    "$rotbeam" "$command" --help >"$work/help" || fail "$command --help: exit $?"
    for option in $(complete_words rotbeam "$command" --); do
        [ "$option" = --help ] && continue
        line=$(grep -E -- "^  $option( |$)" "$work/help")
        [ -n "$line" ] || { fail "$command --help does not list $option"; continue; }
        echo "$line" | grep -Eq "default|required" || fail "$command --help: $option without a default: $line"
        # The parser accepts it (with a value when the help names one); --help then wins.
        args=("$option")
        echo "$line" | grep -Eq -- "^  $option [^ ]" && args+=(x)
        "$rotbeam" "$command" "${args[@]}" --help >/dev/null 2>"$work/err" ||
            fail "$command $option: not accepted: $(cat "$work/err")"
    done
done
[ -n "$commands" ] || fail "the completion offers no command"

# `study --help` names every registered study: the names `rotbeam study` offers for an unknown one.
"$rotbeam" study no-such-study >/dev/null 2>"$work/err" && fail "study no-such-study: exit 0"
studies=$(sed -n 's/.*(available: \(.*\))$/\1/p' "$work/err" | tr -d ,)
[ -n "$studies" ] || fail "study no-such-study names no available study: $(cat "$work/err")"
"$rotbeam" study --help >"$work/help" || fail "study --help: exit $?"
for name in $studies; do
    grep -q "\`$name\`" "$work/help" || fail "study --help does not list the study $name"
done
# So does the line of `study` in the top-level help (the same list, from the registry).
"$rotbeam" --help >"$work/top" || fail "rotbeam --help: exit $?"
listed=$(sed -n 's/^  study  *run a study (\(.*\))$/\1/p' "$work/top" | tr -d ,)
[ "$listed" = "$(echo $studies)" ] ||
    fail "rotbeam --help's study line lists '$listed', rotbeam study takes '$(echo $studies)'"
# An option of `study` that does not apply to the study named is refused: exit 2, one line naming
# the option and the study, nothing run or written (the timeout: without the refusal, the study
# would run).
for refused in "convergence --samples 5" "singularity --json $work/never.json" "rotations --quick" \
    "rotations --out $work/never" "extremes --reduced-follower" "rotations --jobs 2"; do
    read -r -a words <<<"$refused"
    timeout 20 "$rotbeam" study "${words[@]}" >"$work/out" 2>"$work/err"
    code=$?
    [ $code -eq 2 ] || fail "study $refused: exit $code, expected 2"
    [ "$(wc -l <"$work/err")" -eq 1 ] && grep -qF -- "rotbeam study: ${words[1]} does not apply to study '${words[0]}'" "$work/err" ||
        fail "study $refused: '$(cat "$work/err")'"
    [ -s "$work/out" ] && fail "study $refused printed $(head -1 "$work/out")"
done
[ -e "$work/never" ] || [ -e "$work/never.json" ] && fail "a refused study wrote its output"

# Every JSON file carries the schema version --version names: a run's result and verify's table.
schema=$(sed -n 's/.*(JSON schema_version \([0-9]*\)).*/\1/p' "$work/version")
[ -n "$schema" ] || fail "--version names no JSON schema_version: $(head -1 "$work/version")"
"$rotbeam" run cantilever-moment --estimate off --quiet --json "$work/r.json" || fail "run: exit $?"
grep -q "\"schema_version\": $schema," "$work/r.json" || fail "run --json: no schema_version $schema"
# verify's table on a copy of cantilever-moment with two of the catalog's entries, a published value
# (for one combination) and an expected stop: a row of each kind for the summary's count. The whole
# catalog file ran every combination of the case to λ = 2, ~37 of this test's ~50 s under the
# sanitizers (docs/quality-checks.md, Time); that every entry passes is published_gate's check.
cases=${ROTBEAM_CASES:-$(dirname "$0")/../../cases}
mkdir -p "$work/gate/references"
cp "$cases/cantilever-moment.yaml" "$work/gate/"
/usr/bin/python3 - "$cases/references/cantilever-moment.yaml" \
    "$work/gate/references/cantilever-moment.yaml" <<'PY' || fail "could not cut the references"
import sys, yaml
catalog = yaml.safe_load(open(sys.argv[1]))
value = dict(catalog["references"]["exact-0p4"])
value.pop("also", None)
value["applies_to"] = {"formulation": "displacement", "rotation": "quaternion",
                       "interpolation": "relative"}
stop = catalog["expected_stops"]["mixed-rodrigues"]
yaml.safe_dump({"references": {"exact-0p4": value},
                "expected_stops": {"mixed-rodrigues": stop}}, open(sys.argv[2], "w"))
PY
"$rotbeam" verify "$work/gate/cantilever-moment.yaml" --json "$work/v.json" >/dev/null ||
    fail "verify: exit $?"
/usr/bin/python3 - "$work/v.json" "$schema" <<'PY' || fail "verify --json: not a versioned table"
import json, sys
table = json.load(open(sys.argv[1]))
assert table["schema_version"] == int(sys.argv[2]), table.get("schema_version")
assert table["rows"] and all("result" in r for r in table["rows"]), "no rows"
assert {r["quantity"] == "stop" for r in table["rows"]} == {True, False}, "not a row of each kind"
s = table["summary"]
assert s["gated_pairs"] == sum(r["result"] in ("pass", "FAIL") and r["quantity"] != "stop"
                               for r in table["rows"]), s
PY
exit $((failures > 0))
