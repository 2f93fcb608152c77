#!/usr/bin/env python3
"""The make-span of `mpirun -np N rotbeam-mpi ...` predicted from measured unit times.

usage: makespan.py UNITS_CSV [--ranks 1,2,4,...] > TABLE

UNITS_CSV: one line per unit of a job, `unit,seconds,timed` (timed = 1 for a unit run alone after
the others, the speed-accuracy study), as `makespan.py --collect SHARD_DIR` writes it from a shard
folder made by `rotbeam suite|study ... --shard 1/1 --jobs 1` (docs/distributed-runs.md): the
case runs' wall_seconds, the study runs' and whole studies' seconds.

The scheduler simulated is the one of distribution/ranks_mpi.cpp: the units in decreasing
expected time (here: the measured time, as with --timings from an earlier run), each taken by the
first rank that is free (one thread per rank), every request answered after `--latency` seconds
(default 1 ms, the answering thread's polling interval); then the timed units one after another on
rank 0. Printed per rank count: ranks, make-span, the lower bound max(Σ/N, longest) + timed, the
longest unit, and Σ/N.
"""
import heapq
import json
import pathlib
import sys


def collect(folder):
    root = pathlib.Path(folder)
    print("unit,seconds,timed")
    for p in sorted(root.glob("runs/*.json")):
        print(f"{p.stem},{json.loads(p.read_text())['wall_seconds']},0")
    for p in sorted(root.glob("study-runs/*/*.json")):
        j = json.loads(p.read_text())
        print(f"{j['study']}/{p.stem},{j['seconds']},0")
    for p in sorted(root.glob("studies/*.done.json")):
        j = json.loads(p.read_text())
        timed = 1 if j["study"] == "speed-accuracy" else 0
        print(f"study {j['study']},{j['seconds']},{timed}")


def makespan(seconds, ranks, latency):
    free = [0.0] * ranks  # the time each rank becomes free
    heapq.heapify(free)
    for s in sorted(seconds, reverse=True):
        heapq.heappush(free, heapq.heappop(free) + latency + s)
    return max(free)


def main(argv):
    if len(argv) == 3 and argv[1] == "--collect":
        collect(argv[2])
        return 0
    if len(argv) < 2:
        print(__doc__, file=sys.stderr)
        return 2
    ranks = [1, 2, 4, 8, 16, 32, 64, 128, 256, 512, 1024]
    latency = 0.001
    args = argv[2:]
    while args:
        if args[0] == "--ranks":
            ranks = [int(r) for r in args[1].split(",")]
        elif args[0] == "--latency":
            latency = float(args[1])
        args = args[2:]
    pooled, timed = [], 0.0
    for line in pathlib.Path(argv[1]).read_text().splitlines()[1:]:
        _, s, t = line.rsplit(",", 2)
        if t == "1":
            timed += float(s)
        else:
            pooled.append(float(s))
    total, longest = sum(pooled), max(pooled)
    print(f"# {len(pooled)} pooled units, {total:.1f} s in all, longest {longest:.1f} s; "
          f"timed units {timed:.1f} s")
    print("ranks makespan bound longest mean")
    for n in ranks:
        m = makespan(pooled, n, latency) + timed
        print(f"{n} {m:.2f} {max(total / n, longest) + timed:.2f} {longest + timed:.2f} "
              f"{total / n + timed:.2f}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
