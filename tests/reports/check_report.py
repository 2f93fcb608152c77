#!/usr/bin/env python3
"""Checks that a report folder written by `rotbeam suite` is complete and consistent.

Usage: check_report.py DIR. Prints one line per problem and exits 1 if there is any:
- every file a Markdown page (index.md, study-*.md, published.md) or index.html links exists and
  is not empty;
- every number in every table parses: no cell holds nan or inf, and no token that starts like a
  number is malformed;
- no result field holds NaN or an absurd value: the run files (runs/*.json) and the studies'
  JSON hold no NaN/inf, a converged run has a finite number everywhere in its steps, times and
  counts are not negative, element orders lie within the orders a case may ask for (1…24,
  docs/case-format.md, Limits), observed convergence orders are finite numbers of sane size.
"""
import glob
import json
import math
import os
import re
import sys

MAX_ORDER = 24  # cases/loader/limits.hpp, kMaxOrder
problems = []


def problem(where, what):
    problems.append(f"{where}: {what}")


def check_links(folder):
    pages = glob.glob(os.path.join(folder, "*.md"))
    if not pages:
        problem(folder, "no Markdown page")
    for page in pages:
        text = open(page, encoding="utf-8").read()
        for target in re.findall(r"\]\(([^)\s]+)\)", text):
            check_target(page, folder, target)
    html = os.path.join(folder, "index.html")
    if os.path.exists(html):
        text = open(html, encoding="utf-8").read()
        for target in re.findall(r'(?:src|href)="([^"]+)"', text):
            check_target(html, folder, target)


def check_target(page, folder, target):
    if re.match(r"^(https?:|mailto:|data:|#)", target):
        return
    path = os.path.join(folder, target.split("#")[0])
    if not os.path.isfile(path):
        problem(os.path.basename(page), f"links {target}, which does not exist")
    elif os.path.getsize(path) == 0:
        problem(os.path.basename(page), f"links {target}, which is empty")


NUMBER_START = re.compile(r"(?<![\w.])[-+]?\.?\d")
NUMBER = re.compile(r"[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?")
NOT_A_NUMBER = re.compile(r"(?<![\w-])[-+]?(nan|inf|infinity)(?![\w-])", re.IGNORECASE)


def check_prose_orders(folder):
    """Element orders named in the text ("order 4", "orders 2, 4, 6, 8") lie within 1…24."""
    for page in glob.glob(os.path.join(folder, "*.md")):
        text = open(page, encoding="utf-8").read()
        for m in re.finditer(r"\borders? (\d+(?:, \d+)*)\b", text):
            for p in m.group(1).split(", "):
                if not 1 <= int(p) <= MAX_ORDER:
                    problem(os.path.basename(page),
                            f"'{m.group(0)}': element order {p} outside 1…{MAX_ORDER}")


def check_tables(folder):
    for page in glob.glob(os.path.join(folder, "*.md")):
        name = os.path.basename(page)
        for n, line in enumerate(open(page, encoding="utf-8"), 1):
            if not line.startswith("|") or re.match(r"^\|[-:| ]+\|\s*$", line):
                continue
            # Code spans hold keys and commands, not results.
            cells = re.sub(r"`[^`]*`", "", line).strip().strip("|").split("|")
            for cell in cells:
                if NOT_A_NUMBER.search(cell):
                    problem(f"{name}:{n}", f"table cell '{cell.strip()}' holds a non-number")
                for m in NUMBER_START.finditer(cell):
                    token = re.match(r"[-+]?[\w.+-]*", cell[m.start():]).group(0)
                    token = token.rstrip(".-+")
                    lead = NUMBER.match(token)
                    # A number, or a number with a unit or suffix (8s, 1e-3x, 2nd): the numeric
                    # part must be whole (no 1.2.3, no 1e without digits).
                    rest = token[lead.end():] if lead else token
                    if not lead or re.match(r"^[.eE]", rest) or re.match(r"^[.]\d", rest):
                        problem(f"{name}:{n}", f"table cell '{cell.strip()}': malformed number "
                                f"'{token}'")


TIME_KEY = re.compile(r"(seconds|^time$|^times$|cpu|wall)", re.IGNORECASE)
COUNT_KEYS = {"elements", "dofs", "newton_iterations", "iterations", "steps_taken", "repeats"}


def walk(value, where, key, converged_steps):
    if isinstance(value, dict):
        for k, v in value.items():
            walk(v, f"{where}.{k}", k, converged_steps or (k == "steps" and converged_steps))
    elif isinstance(value, list):
        for i, v in enumerate(value):
            walk(v, f"{where}[{i}]", key, converged_steps)
    elif isinstance(value, bool) or isinstance(value, str):
        return
    elif value is None:
        if converged_steps:
            problem(where, "null (NaN) in a converged run's steps")
    elif isinstance(value, (int, float)):
        if not math.isfinite(value):
            problem(where, f"{value}")
            return
        if TIME_KEY.search(key) and value < 0:
            problem(where, f"negative time {value}")
        if key in COUNT_KEYS and value < 0:
            problem(where, f"negative count {value}")
        if key in ("order", "orders") and not (1 <= value <= MAX_ORDER and value == int(value)):
            problem(where, f"element order {value} outside 1…{MAX_ORDER}")
        if key in ("order_ls", "order_tail", "order_before") and abs(value) > 100:
            problem(where, f"observed order {value} is absurd")


def check_results(folder):
    runs = glob.glob(os.path.join(folder, "runs", "*.json"))
    if not runs:
        problem(folder, "no run files in runs/")
    for path in runs + glob.glob(os.path.join(folder, "study-*.json")):
        name = os.path.relpath(path, folder)
        try:
            data = json.load(open(path, encoding="utf-8"))
        except ValueError as e:
            problem(name, f"not JSON: {e}")
            continue
        converged = isinstance(data, dict) and data.get("status") == "converged"
        if isinstance(data, dict) and "steps" in data:
            walk({k: v for k, v in data.items() if k != "steps"}, name, "", False)
            walk(data["steps"], f"{name}.steps", "steps", converged)
        else:
            walk(data, name, "", False)


folder = sys.argv[1]
check_links(folder)
check_tables(folder)
check_prose_orders(folder)
check_results(folder)
for p in problems:
    print("FAIL: " + p)
print(f"report {folder}: " + (f"{len(problems)} problems" if problems else "complete"))
sys.exit(1 if problems else 0)
