#!/usr/bin/env bash
# A rotbeam suite or study over a list of hosts without a batch system (docs/distributed-runs.md):
# shard I of N runs on the I-th host (ssh, in the same folder path), all at once; then the shards
# are merged here into OUT/merged. The host `-` means this machine (no ssh).
#
# usage: scripts/hosts-shards.sh OUT HOST... -- ROTBEAM_ARGUMENTS...
#   e.g. scripts/hosts-shards.sh /shared/rb node1 node2 node3 -- suite --quick
# Environment: ROTBEAM (the program, default: rotbeam on PATH on every host), TIMINGS (an
# earlier output folder whose run times balance the shards; optional), RSH (default ssh).
#
# OUT must be on a file system every host sees. A shard whose host fails keeps its finished runs;
# the merge then exits 5 and lists them with the command to run (on any host): it resumes.
set -u
if [ $# -lt 3 ]; then
    sed -n '6,8p' "$0" >&2
    exit 2
fi
out=$1
shift
hosts=()
while [ $# -gt 0 ] && [ "$1" != "--" ]; do
    hosts+=("$1")
    shift
done
[ "${1:-}" = "--" ] || { echo "hosts-shards.sh: missing -- before the rotbeam arguments" >&2; exit 2; }
shift
rotbeam=${ROTBEAM:-rotbeam}
n=${#hosts[@]}
timings=()
[ -n "${TIMINGS:-}" ] && timings=(--timings "$TIMINGS")
mkdir -p "$out"
pids=()
for i in $(seq 1 "$n"); do
    host=${hosts[$((i - 1))]}
    command=("$rotbeam" "$@" --shard "$i/$n" "${timings[@]}" --out "$out/shard-$i")
    if [ "$host" = "-" ]; then
        "${command[@]}" >"$out/shard-$i.log" 2>&1 &
    else
        ${RSH:-ssh} "$host" "cd $(printf '%q' "$PWD") && $(printf '%q ' "${command[@]}")" \
            >"$out/shard-$i.log" 2>&1 &
    fi
    pids+=($!)
done
status=0
for i in $(seq 1 "$n"); do
    wait "${pids[$((i - 1))]}" || { echo "shard $i/$n on ${hosts[$((i - 1))]} failed: see $out/shard-$i.log" >&2; status=1; }
done
shards=()
for i in $(seq 1 "$n"); do shards+=("$out/shard-$i"); done
"$rotbeam" merge "${shards[@]}" --out "$out/merged"
code=$?
[ $code -eq 0 ] && exit $status
exit $code
