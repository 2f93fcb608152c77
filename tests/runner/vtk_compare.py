#!/usr/bin/env python3
"""Compares the `rotbeam run --vtk` output of one case in two formulations (or discretizations) at
the nodes they share (the same reference_position), file by file, and prints by how much they
differ.

usage: vtk_compare.py A.pvd B.pvd [TOLERANCE [RESULTANT_TOLERANCE]]

Dynamics and statics (files paired by their timestep): the largest distance between the two
positions of a shared node over all files, relative to the largest displacement of A; the largest
entry of R_A − R_B, R = exp(rotation_vector). Modes (paired by number): each file's
mode_displacement at the shared nodes scaled to unit largest component, the sign of B's chosen to
match A's; the largest difference. Statics and dynamics with the section resultants (cell data
section_force, section_moment) in either: both must have them, on the same nodes (so the same
cells), and each field's largest difference relative to its largest value in A is held against
RESULTANT_TOLERANCE (default TOLERANCE). With TOLERANCE the exit status is 1 when a printed
relative difference exceeds it.
"""
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
from vtk_check import rotation_matrix  # noqa: E402 (exp of a rotation vector)


RESULTANTS = ("section_force", "section_moment")


def read_series(pvd):
    """(timestep, point data of the nodes) of every file of a .pvd."""
    out = []
    for dataset in ET.parse(pvd).getroot().find("Collection").findall("DataSet"):
        mesh = meshio.read(os.path.join(os.path.dirname(pvd), dataset.get("file")))
        n = len(mesh.points) // 3
        data = {k: np.asarray(v)[:n] for k, v in mesh.point_data.items()}
        data["position"] = mesh.points[:n]
        for name in RESULTANTS:
            if name in mesh.cell_data:  # the line cells' values (the ribbon's quads repeat them)
                data[name] = np.asarray(mesh.cell_data[name][0])
        out.append((float(dataset.get("timestep")), data))
    return out


def shared_nodes(a, b):
    """Index pairs (i in a, j in b) of the nodes at the same reference position, each once. The
    formulations place their nodes by different arithmetic, so "the same" is within 1e-12 of the
    structure's size: a few ulps of it, while distinct nodes are at least an element apart."""
    ra, rb = a["reference_position"], b["reference_position"]
    within = 1e-12 * max(np.abs(ra).max(), np.abs(rb).max())
    pairs = []
    for i, x in enumerate(ra):
        distance = np.abs(rb - x).max(axis=1)
        j = int(distance.argmin())
        if distance[j] <= within and all(np.abs(ra[k] - x).max() > within for k, _ in pairs):
            pairs.append((i, j))
    return pairs


def main():
    a_series, b_series = read_series(sys.argv[1]), read_series(sys.argv[2])
    tolerance = float(sys.argv[3]) if len(sys.argv) > 3 else None
    resultant_tolerance = float(sys.argv[4]) if len(sys.argv) > 4 else tolerance
    if len(a_series) != len(b_series) or not a_series:
        print(f"vtk_compare: {len(a_series)} files against {len(b_series)}")
        return 1
    modal = "mode_displacement" in a_series[0][1]
    worst_resultant = 0.0
    position = rotation = amplitude = mode = 0.0
    scale = dict.fromkeys(RESULTANTS, 0.0)
    resultant = dict.fromkeys(RESULTANTS, 0.0)
    shared = 0
    for (ta, a), (tb, b) in zip(a_series, b_series):
        if ta != tb:
            print(f"vtk_compare: timestep {ta} against {tb}")
            return 1
        pairs = shared_nodes(a, b)
        shared = len(pairs)
        i, j = np.array([p[0] for p in pairs]), np.array([p[1] for p in pairs])
        if modal:
            ma, mb = a["mode_displacement"][i], b["mode_displacement"][j]
            ma, mb = ma / np.abs(ma).max(), mb / np.abs(mb).max()
            if np.sum(ma * mb) < 0:
                mb = -mb
            mode = max(mode, np.abs(ma - mb).max())
            continue
        # Section resultants, cell by cell, when either file gives them: both must, on the same
        # nodes (so on the same cells, in the same order); relative to each field's largest value
        # in A.
        if any(k in a or k in b for k in RESULTANTS):
            if not all(k in a and k in b for k in RESULTANTS):
                print(f"vtk_compare: at {ta} only one file has section_force and section_moment")
                return 1
            if not shared == len(a["position"]) == len(b["position"]):
                print(f"vtk_compare: at {ta} the resultants are on different cells")
                return 1
            for k in RESULTANTS:
                scale[k] = max(scale[k], np.abs(a[k]).max())
                resultant[k] = max(resultant[k], np.abs(a[k] - b[k]).max())
        amplitude = max(amplitude, np.abs(a["displacement"]).max())
        position = max(position, np.linalg.norm(a["position"][i] - b["position"][j], axis=1).max())
        for k, l in pairs:
            error = rotation_matrix(a["rotation_vector"][k]) - rotation_matrix(b["rotation_vector"][l])
            rotation = max(rotation, np.abs(error).max())
    if modal:
        print(f"vtk_compare: {len(a_series)} modes, {shared} shared nodes: mode shapes (largest "
              f"component 1) differ by {mode:.3g}")
        worst = mode
    else:
        relative = position / amplitude if amplitude > 0 else position
        print(f"vtk_compare: {len(a_series)} files, {shared} shared nodes: positions differ by "
              f"{position:.3g} ({relative:.3g} of the largest displacement {amplitude:.3g}), "
              f"rotation matrices by {rotation:.3g}")
        worst = max(relative, rotation)
        for k in RESULTANTS:
            if scale[k] > 0:
                print(f"vtk_compare: {k} differs by {resultant[k]:.3g} "
                      f"({resultant[k] / scale[k]:.3g} of its largest {scale[k]:.3g})")
                worst_resultant = max(worst_resultant, resultant[k] / scale[k])
    if tolerance is None:
        return 0
    return 1 if worst > tolerance or worst_resultant > resultant_tolerance else 0


if __name__ == "__main__":
    sys.exit(main())
