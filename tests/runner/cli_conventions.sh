#!/usr/bin/env bash
# The conventions a user expects of the command line: --version names the dependencies' versions;
# every option of every command (as the completion script offers it, generated from the same
# tables the parser reads) is accepted by the parser and listed by the command's --help with its
# default; the completion script completes `rotbeam r` and `rotbeam run --f`; every JSON result
# has the schema version. Usage: cli_conventions.sh ROTBEAM COMPLETION_SCRIPT
set -u
rotbeam=$1
script=$2
. "$(dirname "$0")/scratch.sh"

"$rotbeam" --version >"$work/version" || fail "--version: exit $?"
for dep in SUNDIALS Eigen GSL yaml-cpp SuiteSparse KLU Spectra Boost; do
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
[ "$(complete_words rotbeam run --f)" = "--formulation" ] ||
    fail "rotbeam run --f completes to '$(complete_words rotbeam run --f)'"

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

"$rotbeam" run cantilever-moment --estimate off --quiet --json "$work/r.json" || fail "run: exit $?"
grep -q '"schema_version": 1' "$work/r.json" || fail "run --json: no schema_version 1"
exit $((failures > 0))
