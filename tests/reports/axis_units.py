#!/usr/bin/python3
"""Every axis label of the report's and the studies' figures names its unit in brackets: `[s]`,
`[in]`, `[rad]`, and `[-]` for a ratio, a load factor or a count.

Usage: axis_units.py SOURCE_DIR. Reads the labels where they are written: `set xlabel "…"` (and
ylabel, zlabel) in reports/*.gp, and the label literals the studies and benches hand to those
scripts (`{"xlabel", "…"}`, `{"ylabel", "…"}` and the literal labels of their figure tables) in
studies/*.cpp and benches/*.cpp. A label computed at run time from a variable is checked where
its literal is written, when that is one of the forms above. Prints one line per label without a
unit and exits 1 if there is any.
"""
import glob
import os
import re
import sys

UNIT = re.compile(r"\[[^\]]+\]")
GNUPLOT = re.compile(r'set [xyz]label "([^"]*)"')
CPP = re.compile(r'\{"[xy]label",([^}]*)\}')  # the literals of the value, joined
# study_singularity: a label chosen by a conditional, both branches literal.
CONDITIONAL = re.compile(r'(?:x|y)label = [^;]*?\? "([^"]*)"\s*:\s*((?:"[^"]*"\s*)+);', re.S)
# study_manufactured_time: the figure table's x and y labels, "time step Δt [s]", "… [-]".
TABLE_ROW = re.compile(r'titles, "[0-9]+", "[0-9]+",\s*"([^"]*)",\s*"([^"]*)"', re.S)


def labels(root):
    for path in sorted(glob.glob(os.path.join(root, "reports", "*.gp"))):
        for label in GNUPLOT.findall(open(path, encoding="utf-8").read()):
            yield path, label
    for path in sorted(glob.glob(os.path.join(root, "studies", "*.cpp")) +
                       glob.glob(os.path.join(root, "benches", "*.cpp"))):
        text = open(path, encoding="utf-8").read()
        for value in CPP.findall(text):
            literal = "".join(re.findall(r'"([^"]*)"', value))
            if literal:  # a bare variable (c.ylabel) is checked where its literal is written
                yield path, literal
        for first, rest in CONDITIONAL.findall(text):
            yield path, first
            yield path, "".join(re.findall(r'"([^"]*)"', rest))
        for x, y in TABLE_ROW.findall(text):
            yield path, x
            yield path, y


def main():
    root = sys.argv[1]
    seen = 0
    missing = []
    for path, label in labels(root):
        seen += 1
        if not UNIT.search(label):
            missing.append(f"{os.path.relpath(path, root)}: axis label without a unit: {label!r}")
    for line in missing:
        print("FAIL:", line)
    print(f"axis_units: {seen} labels, {len(missing)} without a unit")
    # Fewer than 40 would mean the patterns no longer find the labels (measured: 57, 2026-11-27).
    if seen < 40:
        print("FAIL: too few labels found; the patterns no longer match the sources")
        return 1
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
