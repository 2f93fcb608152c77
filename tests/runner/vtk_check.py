#!/usr/bin/env python3
"""Reads `rotbeam run --vtk` output back with meshio (an independent VTK reader) and checks its
geometry against the run's JSON.

usage: vtk_check.py PVD RESULT.json CASE.yaml

Checks: the .pvd lists one file per reported step (or mode) with its load factor, time or mode
number; every file reads; the line cells join the nodes of each member in order; the node at every
named point (found by its reference_position, which equals the case's point) is at the case's
position + the JSON displacement of that step (modes: the mode amplitude equals the JSON's, the
position that of the last static step about which the modes are); with a
`centerline` in the JSON (the displacement formulation's statics), every node equals it; the
directors are orthonormal and right-handed; a static step's error estimate is point data at the
named points' nodes (−1 elsewhere) equal to the JSON's; the ribbon's edges are the node ± h d2
with one h for all nodes; the ribbon turns with the section as the JSON says: at every named point
exp(rotation_vector)ᵀ [d1 d2 d3], the reference frame R^r(s), is the same in every file (so twist and
the turning frame's rotation show); with turning supports (`rotating_frame` in the JSON) the nodes
are at the inertial position (the JSON's `points`) and relative_displacement equals the JSON's
`rotating_frame.points` displacement.

Tolerances: every double is written with 17 significant digits, so it reads back exactly. A node's
position is x^r + u rounded once by rotbeam; here the case's x^r + the JSON's u (also exact) is
rounded once more: each rounding is at most ε/2 of the magnitude, so the two agree within
ε·scale (scale: the largest magnitude among x^r, u, x). A mode amplitude is the same double in
both files: within 4ε of the normalized amplitude 1 only as a margin for the decimal round trip.
The directors are columns of a product of rotation matrices, orthonormal to a few ε: 1e-13 leaves
room for the ~10 operations per entry and catches any wrong column (an error of order one). The
ribbon edge x ∓ h d2 is rounded once per component: within 2ε·scale. The reference frame
exp(ψ)ᵀ D (and the rotation, exp of the file's rotation_vector against exp of the JSON's): ψ is
the principal rotation vector of R rounded to 17 digits, exp here (Rodrigues) and the product add
a few ε per entry; 1e-12 leaves room for the loss near a half turn (the roll-up passes π) and
still catches a frame off by a turn of 1e-12 rad, far below any visible twist (a
missing turning frame is off by Ω t, here ≥ 0.01 rad). The relative displacement is the JSON's
double written once: within ε·scale.
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np
import yaml

EPS = np.finfo(float).eps
failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def rotation_matrix(psi):
    """exp of the rotation vector psi (Rodrigues' formula)."""
    angle = np.linalg.norm(psi)
    K = np.array([[0, -psi[2], psi[1]], [psi[2], 0, -psi[0]], [-psi[1], psi[0], 0]])
    if angle < 1e-8:  # the series to second order: its remainder is below 1e-24
        return np.eye(3) + K + K @ K / 2
    return np.eye(3) + np.sin(angle) / angle * K + (1 - np.cos(angle)) / angle**2 * K @ K


reference_frames = {}  # per named point: exp(ψ)ᵀ D of the first file


def main():
    pvd, result_path, case_path = sys.argv[1:4]
    result = json.load(open(result_path))
    case = yaml.safe_load(open(case_path))
    entries = result["modes"] if "modes" in result else result["steps"]
    datasets = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
    check(len(datasets) == len(entries) > 0,
          f"{len(datasets)} files in the .pvd for {len(entries)} steps or modes")
    for index, (entry, dataset) in enumerate(zip(entries, datasets)):
        expected = index + 1 if "modes" in result else entry.get("time", entry.get("load_factor"))
        check(float(dataset.get("timestep")) == expected,
              f"file {index}: timestep {dataset.get('timestep')} != {expected}")
        mesh = meshio.read(os.path.join(os.path.dirname(pvd), dataset.get("file")))
        check_file(index, mesh, entry, result, case)
    for f in failures[:20]:
        print("FAIL:", f)
    print(f"vtk_check: {len(datasets)} files, {len(failures)} failure(s)")
    return 1 if failures else 0


def check_file(index, mesh, entry, result, case):
    where = f"file {index}"
    lines = next(c.data for c in mesh.cells if c.type == "line")
    quads = next(c.data for c in mesh.cells if c.type == "quad")
    n = len(mesh.points) // 3
    check(len(mesh.points) == 3 * n and len(quads) == len(lines), f"{where}: point/cell counts")
    data = mesh.point_data
    x = mesh.points[:n]
    member = data["member"][:n].ravel()
    # Line cells: neighbouring nodes of one member, in order.
    check(all(b == a + 1 and member[a] == member[b] for a, b in lines), f"{where}: line cells")
    # The named points: at the case's position + the JSON displacement.
    ref = data["reference_position"][:n]
    for name, point in entry["points"].items():
        x0 = np.array(case["points"][name], dtype=float)
        at = [i for i in range(n) if np.array_equal(ref[i], x0)]
        check(len(at) > 0, f"{where}: no node at the point {name}")
        if "modes" in result:
            # The state the mode is about: the last static step's where the result has one (a
            # modal analysis about a static state), else the file's own.
            u = data["displacement"][at[0]] if at else x0 * 0
            if result.get("steps"):
                u = np.array(result["steps"][-1]["points"][name]["displacement"], dtype=float)
            for i in at:
                check(np.abs(data["mode_displacement"][i] - point["displacement"]).max() <= 4 * EPS,
                      f"{where}: {name}: mode amplitude {data['mode_displacement'][i]} != "
                      f"{point['displacement']}")
        else:
            u = np.array(point["displacement"], dtype=float)
        expected = x0 + u
        scale = max(np.abs(x0).max(), np.abs(u).max(), np.abs(expected).max())
        for i in at:
            error = np.abs(x[i] - expected).max()
            check(error <= EPS * scale,
                  f"{where}: {name}: node {x[i]} != reference + displacement {expected}")
        if "modes" not in result and at:
            check_rotation(where, name, data, at[0], point["rotation_vector"])
            check_twist(where, name, data, at[0], point["rotation_vector"])
        if "modes" in result and "rotation" in point:
            for i in at:
                check(np.abs(data["mode_rotation"][i] - point["rotation"]).max() <= 4 * EPS,
                      f"{where}: {name}: mode rotation {data['mode_rotation'][i]} != "
                      f"{point['rotation']}")
        if "rotating_frame" in entry and at:
            relative = np.array(entry["rotating_frame"]["points"][name]["displacement"])
            check("relative_displacement" in data, f"{where}: no relative_displacement")
            if "relative_displacement" in data:
                got = data["relative_displacement"][at[0]]
                check(np.abs(got - relative).max() <= EPS * max(np.abs(relative).max(), 1e-300),
                      f"{where}: {name}: relative displacement {got} != JSON {relative}")
    if "estimate" in entry and "modes" not in result:
        check_estimate(where, data, entry, ref, case)
    if "stations" in entry:
        check_stations(where, ref, data["mode_displacement"][:n], member,
                       entry["stations"], case)
    if "centerline" in entry:
        line = np.array([p[1:] for p in entry["centerline"]])
        check(line.shape == x.shape and np.abs(line - x).max() <= EPS * np.abs(line).max(),
              f"{where}: nodes differ from the JSON centerline")
    d = [data[f"director_{k}"][:n] for k in (1, 2, 3)]
    for i in range(n):
        R = np.column_stack([d[0][i], d[1][i], d[2][i]])
        check(np.abs(R.T @ R - np.eye(3)).max() <= 1e-13 and np.linalg.det(R) > 0,
              f"{where}: node {i}: directors not a rotation")
    h = np.linalg.norm(mesh.points[2 * n:] - x, axis=1)
    scale = np.abs(mesh.points).max()
    check(np.abs(mesh.points[n:2 * n] - (x - h[:, None] * d[1])).max() <= 2 * EPS * scale and
          np.ptp(h) <= 2 * EPS * scale, f"{where}: ribbon edges are not x -+ h d2")


def check_estimate(where, data, entry, ref, case):
    """The step's error estimate as point data: at the node of every named point (and the ribbon's
    points beside it) the JSON's estimated error of its displacement and rotation, and
    `reliable` as 1/0; −1 ("no estimate") at every other point. Read back exactly."""
    n = len(ref)
    estimate = entry["estimate"]
    for quantity in ("displacement", "rotation"):
        name = f"estimate_{quantity}"
        check(name in data and f"{name}_reliable" in data, f"{where}: no {name} point data")
        if name not in data or f"{name}_reliable" not in data:
            continue
        error, reliable = np.full(n, -1.0), np.full(n, -1.0)
        for point in entry["points"]:
            q = estimate.get(point, estimate).get(quantity)
            if not isinstance(q, dict) or "error" not in q:
                continue
            at = np.all(ref == np.array(case["points"][point], dtype=float), axis=1)
            error[at] = q["error"]
            reliable[at] = 1.0 if q.get("reliable", False) else 0.0
        for array, expected in ((name, error), (f"{name}_reliable", reliable)):
            got = np.asarray(data[array]).ravel()
            check(np.array_equal(got, np.tile(expected, 3)),
                  f"{where}: {array} differs from the JSON's estimate (-1 elsewhere)")


def check_rotation(where, name, data, i, psi):
    """The rotation at a named point's node is the JSON's: exp of the file's rotation_vector (the
    principal value) equals exp of the JSON's (continued along the beam, so it may differ by a
    multiple of 2π in angle)."""
    got = rotation_matrix(np.array(data["rotation_vector"][i], dtype=float))
    error = np.abs(got - rotation_matrix(np.array(psi, dtype=float))).max()
    check(error <= 1e-12, f"{where}: {name}: rotation off the JSON's by {error:.3g}")


def check_stations(where, ref, amplitude, member, stations, case):
    """A mode's `stations` (the JSON's shape along every member: the node amplitudes interpolated
    linearly along the member's chord at equally spaced stations, runs/mode_matching.cpp) from
    the file's mode_displacement at the nodes, the same interpolation, up to one scale factor (the
    displacement formulation's stations are of the unnormalized shape). Tolerance: the amplitudes
    are the same doubles in both (or the JSON's divided by the peak, one rounding); a station's
    chord parameter t is computed here by other arithmetic than rotbeam's, a few ε apart, which
    moves the interpolated value by a few ε times the slope |Δu|/Δt ≤ 2 × the element count (≤ 20
    here) of the largest amplitude: 64 ε of it. A wrong node order, mode or normalization is off
    by order one (measured: one member's interior amplitudes reversed, 0.64 of 0.78)."""
    got = []
    per_member = len(stations) // (3 * len(case["members"]))
    for m, spec in enumerate(case["members"].values()):
        a = np.array(case["points"][spec["from"]], dtype=float)
        d = np.array(case["points"][spec["to"]], dtype=float) - a
        on = sorted(((ref[i] - a) @ d / (d @ d), i) for i in range(len(ref)) if member[i] == m)
        t_nodes = np.array([t for t, _ in on])
        u_nodes = np.array([amplitude[i] for _, i in on])
        for k in range(per_member):
            t = k / (per_member - 1)
            j = 1
            while j + 1 < len(on) and t_nodes[j] < t:
                j += 1
            w = (t - t_nodes[j - 1]) / (t_nodes[j] - t_nodes[j - 1])
            got.extend((1 - w) * u_nodes[j - 1] + w * u_nodes[j])
    got, want = np.array(got), np.array(stations, dtype=float)
    scale = (got @ want) / (got @ got) if got @ got > 0 else 0.0
    error = np.abs(scale * got - want).max()
    check(len(got) == len(want) and error <= 64 * EPS * np.abs(want).max(),
          f"{where}: mode_displacement along the members differs from the JSON stations by "
          f"{error:.3g} (of {np.abs(want).max():.3g})")


def check_twist(where, name, data, i, psi):
    """The section frame at a named point's node, turned back by the JSON's rotation, is the same
    reference frame R^r(s) in every file."""
    D = np.column_stack([data[f"director_{k}"][i] for k in (1, 2, 3)])
    reference = rotation_matrix(np.array(psi, dtype=float)).T @ D
    first = reference_frames.setdefault(name, reference)
    error = np.abs(reference - first).max()
    check(error <= 1e-12, f"{where}: {name}: directors do not turn with the JSON rotation "
          f"(reference frame off by {error:.3g})")


if __name__ == "__main__":
    sys.exit(main())
