#!/usr/bin/env python3
"""Compares two `rotbeam bench --history` files like for like.

usage: scripts/compare-bench.py OLD.json NEW.json [--time-ratio R] [--any-machine]

Both files must come from the same machine tag (timings of different machines are not compared;
--any-machine compares them anyway and says so). For every target and combination present in
both, it prints the status, the discretization, the whole-process and in-process medians and the
accuracy, old -> new, and flags
  - a combination that reached its target and no longer does;
  - an error that grew more than tenfold (and above 1e-14) on the same discretization — an
    optimization must not change results beyond round-off;
  - a median time that grew by more than R (default 1.25) on the same discretization.
A changed discretization is reported, not timed against the old one (it is another computation).
Exit 0: no flag; 1: a flag; 2: bad input (one line naming the file and the problem).
"""
import json
import sys


def fail_input(message):
    print(message, file=sys.stderr)
    sys.exit(2)


def load(path):
    try:
        with open(path, encoding="utf-8") as f:
            data = json.load(f)
    except (OSError, ValueError) as e:
        fail_input(f"{path}: (file): not a bench history file ({e})")
    if not isinstance(data, dict) or "targets" not in data or "machine" not in data:
        fail_input(f"{path}: targets: missing (not written by `rotbeam bench`)")
    return data


def combination(result):
    if "combination" in result:
        return result["combination"]
    return f'{result.get("formulation", "?")}/{result.get("rotation", "?")}'


def discretization(result):
    w = result.get("winner")
    if not isinstance(w, dict):
        return None
    if "discretization" in w:
        return str(w["discretization"])
    # Files written before `solver.mip` existed have no "mip": they ran without it.
    w = dict(w, mip=bool(w.get("mip", False)))
    keys = ("elements", "order", "substeps", "mip")
    return " ".join(f"{k}={w[k]}" for k in keys if k in w)


def seconds(result, key):
    value = result.get(key)
    return value if isinstance(value, (int, float)) and value > 0 else None


def error_of(result):
    w = result.get("winner")
    return w.get("error") if isinstance(w, dict) else None


def reached(result):
    return result.get("status") == "reached"


def ms(value):
    return "—" if value is None else f"{value * 1e3:.2f}"


def main(argv):
    args = [a for a in argv if not a.startswith("--")]
    options = [a for a in argv if a.startswith("--")]
    ratio_limit, any_machine = 1.25, False
    for o in options:
        if o.startswith("--time-ratio="):
            try:
                ratio_limit = float(o.split("=", 1)[1])
            except ValueError:
                fail_input(f"(arguments): --time-ratio: not a number: {o}")
        elif o == "--any-machine":
            any_machine = True
        else:
            fail_input(f"(arguments): {o}: unknown option")
    if len(args) != 2:
        fail_input("(arguments): usage: compare-bench.py OLD.json NEW.json [--time-ratio=R]")
    old, new = load(args[0]), load(args[1])
    old_tag, new_tag = old["machine"].get("tag"), new["machine"].get("tag")
    if old_tag != new_tag:
        if not any_machine:
            fail_input(f"{args[1]}: machine.tag: {new_tag} is not {old_tag}: timings of different "
                       "machines are not compared (--any-machine to compare anyway)")
        print(f"warning: machines differ ({old_tag} / {new_tag}): times are not like for like")
    print(f"{args[0]} ({old.get('date', '?')}, {old.get('version', '?')}) -> "
          f"{args[1]} ({new.get('date', '?')}, {new.get('version', '?')}), machine {new_tag}")
    flags = []
    old_targets = {t["name"]: t for t in old["targets"]}
    for target in new["targets"]:
        before = old_targets.get(target["name"])
        if before is None:
            print(f"\n{target['name']}: new target (nothing to compare)")
            continue
        print(f"\n{target['name']}")
        previous = {combination(r): r for r in before.get("results", [])}
        for r in target.get("results", []):
            name = combination(r)
            p = previous.get(name)
            if p is None:
                print(f"  {name:32s} new combination")
                continue
            same = discretization(p) == discretization(r)
            line = f"  {name:32s} {p.get('status', '?')} -> {r.get('status', '?')}"
            if reached(p) and not reached(r):
                flags.append(f"{target['name']} {name}: reached before, {r.get('status')} now")
            if not same:
                line += f"; discretization {discretization(p)} -> {discretization(r)}"
            for key, label in (("whole_process_seconds", "whole"),
                               ("in_process_seconds", "in process")):
                a, b = seconds(p, key), seconds(r, key)
                if a is None or b is None:
                    continue
                line += f"; {label} {ms(a)} -> {ms(b)} ms ({b / a:.2f}×)"
                if same and b / a > ratio_limit:
                    flags.append(f"{target['name']} {name}: {label} time {b / a:.2f}× "
                                 f"({ms(a)} -> {ms(b)} ms) on the same discretization")
            ea, eb = error_of(p), error_of(r)
            if isinstance(ea, (int, float)) and isinstance(eb, (int, float)):
                line += f"; error {ea:.3g} -> {eb:.3g}"
                if same and eb > 10.0 * ea and eb > 1e-14:
                    flags.append(f"{target['name']} {name}: error {ea:.3g} -> {eb:.3g} on the "
                                 "same discretization")
            print(line)
    print()
    for f in flags:
        print(f"FLAG {f}")
    print(f"{len(flags)} flag(s); time ratio limit {ratio_limit}")
    return 1 if flags else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
