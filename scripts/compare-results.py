#!/usr/bin/env python3
"""Are two rotbeam output folders the same result? (docs/durability.md)

usage: compare-results.py [--relative TOL] DIR_A DIR_B

"Identical" means: the two folders hold the same files (names, recursively; no temporary
left by an interrupted write in either), every JSON file parses (none is truncated), and every
JSON file is equal in both, number for number and string for string, after removing the fields
below. They are the measured timings and what is computed from them; nothing else may differ
between two runs, between `--jobs 1` and `--jobs 2`, or between a resumed and an uninterrupted
suite. Files other than JSON (Markdown, HTML, data for the plots, PNG) carry the same timings
in text and are only required to exist in both.

With --relative TOL, floating-point numbers may differ by TOL relative to their scale: the larger
of the two magnitudes, or, for a number inside a list, the largest magnitude in that list (a
displacement component of 1e-17 beside components of order one is round-off of the same size).
Integers and strings (statuses, iteration and step counts) must still be equal. This is the check
that a restructuring changed no result beyond round-off; the largest relative difference found is
printed.

A run stopped by its wall-clock limit (`--time-limit`: the status `time-limit` in the run's file,
at its top or in a run inside it, such as a companion of its estimate) depends on the machine's
speed, not on its inputs: such a file is left out of the comparison when either folder's copy is
one (it must still exist in both), and the output names how many were left out.

Exit 0 when identical, 1 with one line per difference (at most 40) otherwise.
"""
import json
import os
import sys

# The one list of what may differ. Each entry: a key, removed wherever it occurs in a JSON
# document, and why it is not a result. These are every timing-dependent key `rotbeam suite` and
# `rotbeam run` write; the bench and the standalone timed studies are not covered.
EXCLUDED = {
    # Measured times.
    "wall_seconds": "wall time of a run (runs/*.json, `rotbeam run --json`)",
    "seconds": "time to solution of a speed-study point, or its Pareto-front entry",
    "seconds_all": "speed study: time of a run assembling every term",
    "seconds_needed": "speed study: time of the same run assembling only the needed terms",
    "cpu_seconds": "error estimate: CPU time of the companion runs (estimate.cost)",
    "run_wall_seconds": "error estimate: wall time of the run it estimates (estimate.cost)",
    "run_seconds": "accuracy control: time of one attempt's run (accuracy.attempts)",
    "estimate_seconds": "accuracy control: time of one attempt's estimate (accuracy.attempts)",
    # Derived from the times.
    "ratio": "speed study: seconds_all / seconds_needed",
    "wall_ratio": "error estimate: the companions' wall time over the run's (estimate.cost)",
    "repeats": "speed study: how many repeats fit its time budget",
    "front": "speed study: the Pareto front of time against error (which points, in what order)",
    "winners": "speed study: the cheapest run reaching each accuracy level (chosen by its time)",
}

TEMPORARY_MARKER = ".rotbeam-tmp."
TIME_LIMIT_STATUS = "time-limit"


def stopped_by_time_limit(value):
    """Whether the document, or a run inside it, has the status time-limit."""
    if isinstance(value, dict):
        if value.get("status") == TIME_LIMIT_STATUS:
            return True
        return any(stopped_by_time_limit(v) for v in value.values())
    if isinstance(value, list):
        return any(stopped_by_time_limit(v) for v in value)
    return False


def strip(value):
    if isinstance(value, dict):
        return {k: strip(v) for k, v in value.items() if k not in EXCLUDED}
    if isinstance(value, list):
        return [strip(v) for v in value]
    return value


RELATIVE = None  # --relative TOL, or None for exact equality
largest = [0.0, ""]  # the largest relative difference accepted under --relative, and where


def is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def numbers_close(a, b, scale, where):
    if RELATIVE is None or a == b:
        return a == b
    scale = max(scale, abs(a), abs(b))
    relative = abs(a - b) / scale
    if relative > RELATIVE:
        return False
    if relative > largest[0]:
        largest[0], largest[1] = relative, where
    return True


def first_difference(a, b, where, scale=0.0):
    if is_number(a) and is_number(b) and (isinstance(a, float) or isinstance(b, float)):
        return None if numbers_close(a, b, scale, where) else f"{where}: {a!r} != {b!r}"
    if type(a) is not type(b):
        return f"{where}: {a!r} != {b!r}"
    if isinstance(a, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                return f"{where}.{k}: present in one only"
            d = first_difference(a[k], b[k], f"{where}.{k}")
            if d:
                return d
        return None
    if isinstance(a, list):
        if len(a) != len(b):
            return f"{where}: {len(a)} items != {len(b)}"
        magnitudes = [abs(v) for v in a + b if is_number(v)]
        list_scale = max(magnitudes, default=0.0)
        for i, (x, y) in enumerate(zip(a, b)):
            d = first_difference(x, y, f"{where}[{i}]", list_scale)
            if d:
                return d
        return None
    return None if a == b else f"{where}: {a!r} != {b!r}"


def files(root):
    found = set()
    for directory, _, names in os.walk(root):
        for n in names:
            found.add(os.path.relpath(os.path.join(directory, n), root))
    return found


def load(path, problems):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        problems.append(f"{path}: not complete JSON ({e})")
        return None


def main():
    global RELATIVE
    args = sys.argv[1:]
    if len(args) == 4 and args[0] == "--relative":
        RELATIVE = float(args[1])
        args = args[2:]
    if len(args) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    a_root, b_root = args
    a_files, b_files = files(a_root), files(b_root)
    problems = []
    for name in sorted(a_files | b_files):
        if TEMPORARY_MARKER in name:
            problems.append(f"{name}: temporary file left behind")
        elif name not in a_files or name not in b_files:
            problems.append(f"{name}: only in {a_root if name in a_files else b_root}")
    compared = 0
    time_limited = []
    for name in sorted(a_files & b_files):
        if not name.endswith(".json") or TEMPORARY_MARKER in name:
            continue
        a = load(os.path.join(a_root, name), problems)
        b = load(os.path.join(b_root, name), problems)
        if a is None or b is None:
            continue
        if stopped_by_time_limit(a) or stopped_by_time_limit(b):
            time_limited.append(name)
            continue
        compared += 1
        d = first_difference(strip(a), strip(b), "")
        if d:
            problems.append(f"{name}: {d}")
    if time_limited:
        shown = ", ".join(time_limited[:5]) + (", ..." if len(time_limited) > 5 else "")
        print(f"left out {len(time_limited)} JSON file(s) of runs stopped by the time limit "
              f"(status {TIME_LIMIT_STATUS}): {shown}")
    for p in problems[:40]:
        print(p)
    if problems:
        print(f"{len(problems)} difference(s) between {a_root} and {b_root}")
        return 1
    within = "" if RELATIVE is None else (
        f"; within {RELATIVE:g} relative, largest difference {largest[0]:.3g}"
        + (f" at {largest[1]}" if largest[1] else ""))
    print(f"identical: {compared} JSON files, {len(a_files)} files "
          f"(excluding {len(EXCLUDED)} timing fields){within}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
