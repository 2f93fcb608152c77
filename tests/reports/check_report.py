#!/usr/bin/env python3
"""Checks that a report folder written by `rotbeam suite` is complete and consistent.

Usage: check_report.py DIR. Prints one line per problem and exits 1 if there is any:
- every file a Markdown page (index.md, study-*.md, published.md) or index.html links exists and
  is not empty;
- every number in every table parses: no cell holds nan or inf, and no token that starts like a
  number is malformed;
- no result field holds NaN or an absurd value: the run files (runs/*.json) and the studies'
  JSON hold no NaN/inf, a converged run has a finite number everywhere in its steps, times and
  counts are not negative, observed convergence orders are finite numbers of sane size;
- element orders lie within the range that was run, where the report's data says it: a
  displacement run's `order` is its own mesh's (a member of E elements of order p has E·p + 1
  nodes, which its centerline lists); the orders a study page names are among those its JSON
  records for its series (`orders`, the convergence study's); elsewhere within the orders a case
  may ask for (1…24, docs/case-format.md, Limits);
- the data files the suite writes (*.dat for the figures, *.csv histories and tables) hold no
  nan or inf: a value that does not apply is gnuplot's missing marker `?` or an empty CSV field.
"""
import csv
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


def recorded_orders(study_json):
    """The element orders a study's JSON records for its series (`orders`), or None."""
    try:
        data = json.load(open(study_json, encoding="utf-8"))
    except (OSError, ValueError):
        return None  # check_results names the file
    found = set()

    def collect(value):
        if isinstance(value, dict):
            if isinstance(value.get("orders"), list):
                found.update(o for o in value["orders"] if isinstance(o, int))
            for v in value.values():
                collect(v)
        elif isinstance(value, list):
            for v in value:
                collect(v)

    collect(data)
    return found or None


def check_prose_orders(folder):
    """Element orders named in the text ("order 4", "orders 2, 4, 6, 8") are among the orders the
    study ran where its JSON records them, else within 1…24."""
    for page in glob.glob(os.path.join(folder, "*.md")):
        text = open(page, encoding="utf-8").read()
        ran = recorded_orders(page[:-3] + ".json") if os.path.basename(page).startswith(
            "study-") else None
        for m in re.finditer(r"\borders? (\d+(?:, \d+)*)\b", text):
            for p in m.group(1).split(", "):
                if ran is not None and int(p) not in ran:
                    problem(os.path.basename(page),
                            f"'{m.group(0)}': element order {p} outside the orders the study ran "
                            f"({', '.join(map(str, sorted(ran)))})")
                elif not 1 <= int(p) <= MAX_ORDER:
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
            problem(where, f"{value} (NaN or infinite)")
            return
        if TIME_KEY.search(key) and value < 0:
            problem(where, f"negative time {value}")
        if key in COUNT_KEYS and value < 0:
            problem(where, f"negative count {value}")
        if key in ("order", "orders") and not (1 <= value <= MAX_ORDER and value == int(value)):
            problem(where, f"element order {value} outside 1…{MAX_ORDER}")
        if key in ("order_ls", "order_tail", "order_before") and abs(value) > 100:
            problem(where, f"observed order {value} is absurd")


def check_run_order(name, data):
    """A displacement run's element order is its mesh's: a member of E elements of order p has
    E·p + 1 nodes, one centerline point each (single-member runs; the mixed formulation's elements
    have their own order, whatever `order` says)."""
    members = data.get("elements_per_member")
    order = data.get("order")
    if data.get("formulation") != "displacement" or not isinstance(members, dict) or \
            len(members) != 1 or not isinstance(order, int):
        return
    elements = next(iter(members.values()))
    for step in data.get("steps") or []:
        nodes = len(step.get("centerline") or []) if isinstance(step, dict) else 0
        if nodes:
            if nodes != elements * order + 1:
                problem(name, f"element order {order} outside the run's own: its centerline has "
                        f"{nodes} nodes on {elements} elements (order {(nodes - 1) / elements:g})")
            return


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
        if isinstance(data, dict):
            check_run_order(name, data)
        if isinstance(data, dict) and "steps" in data:
            walk({k: v for k, v in data.items() if k != "steps"}, name, "", False)
            walk(data["steps"], f"{name}.steps", "steps", converged)
        else:
            walk(data, name, "", False)


def check_data_files(folder):
    """No nan or inf in the data the suite writes: whitespace-separated *.dat (comments skipped)
    and *.csv fields; a text field (a status, a message) is not a number and not checked."""
    for path in sorted(glob.glob(os.path.join(folder, "**", "*.dat"), recursive=True) +
                       glob.glob(os.path.join(folder, "**", "*.csv"), recursive=True)):
        name = os.path.relpath(path, folder)
        with open(path, encoding="utf-8", newline="") as f:
            if path.endswith(".csv"):
                rows = ((n, row) for n, row in enumerate(csv.reader(f), 1))
            else:
                rows = ((n, line.split()) for n, line in enumerate(f, 1)
                        if not line.lstrip().startswith("#"))
            for n, fields in rows:
                for field in fields:
                    try:
                        value = float(field)
                    except ValueError:
                        continue
                    if not math.isfinite(value):
                        problem(f"{name}:{n}", f"'{field}' (NaN or infinite) in a data file")
                        break


folder = sys.argv[1]
check_links(folder)
check_tables(folder)
check_prose_orders(folder)
check_results(folder)
check_data_files(folder)
for p in problems:
    print("FAIL: " + p)
print(f"report {folder}: " + (f"{len(problems)} problems" if problems else "complete"))
sys.exit(1 if problems else 0)
