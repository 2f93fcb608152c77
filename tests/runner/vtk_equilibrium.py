#!/usr/bin/env python3
"""Checks the section resultants of `rotbeam run --vtk` on a single-member cantilever under a dead
tip force against statics: the part of the beam beyond a section carries the tip force λP alone,
so at every section the force is F = λP and the moment M = (x_tip − x) × λP, exactly, however far
the beam deflects; on the undeformed line this is the beam-theory closed form M = λP (L − x) (for
a transverse P along e3 of a beam along e1: M = −λP (L − x) e2).

usage: vtk_equilibrium.py PVD Px,Py,Pz TOLERANCE

In every file (λ its TimeValue, the load factor) and for every line cell: section_force against
λP, and section_moment against (x_tip − x_c) × λP, x_c the midpoint of the cell's two deformed
nodes and x_tip the node of largest arc length; both within TOLERANCE × λ|P| (the moment in units
of λ|P| L). Also the closed form on the reference line, M^r = (x^r_tip − x^r_c) × λP: it differs
from the deformed one by (u_tip − u_c) × λP, so by at most 2 max|u| λ|P|, held with that bound.
Prints the largest differences; exit status 1 when one exceeds its tolerance.
"""
import os
import sys
import xml.etree.ElementTree as ET

import meshio
import numpy as np


def main():
    pvd, force, tolerance = sys.argv[1], sys.argv[2], float(sys.argv[3])
    P = np.array([float(x) for x in force.split(",")])
    worst_force = worst_moment = worst_reference = 0.0
    failed = False
    files = ET.parse(pvd).getroot().find("Collection").findall("DataSet")
    for dataset in files:
        mesh = meshio.read(os.path.join(os.path.dirname(pvd), dataset.get("file")))
        lam = float(dataset.get("timestep"))
        n = len(mesh.points) // 3
        x = mesh.points[:n]
        xr = np.asarray(mesh.point_data["reference_position"])[:n]
        s = np.asarray(mesh.point_data["arc_length"])[:n].ravel()
        u = np.asarray(mesh.point_data["displacement"])[:n]
        lines = next(block.data for block in mesh.cells if block.type == "line")
        if "section_force" not in mesh.cell_data or "section_moment" not in mesh.cell_data:
            print(f"vtk_equilibrium: {dataset.get('file')}: no section_force/section_moment")
            return 1
        F = np.asarray(mesh.cell_data["section_force"][0])
        M = np.asarray(mesh.cell_data["section_moment"][0])
        if len(F) != len(lines):
            print(f"vtk_equilibrium: {len(F)} resultants for {len(lines)} line cells")
            return 1
        tip = int(s.argmax())
        length = s.max() - s.min()
        load = lam * P
        scale = np.linalg.norm(load)
        mid = 0.5 * (x[lines[:, 0]] + x[lines[:, 1]])
        mid_r = 0.5 * (xr[lines[:, 0]] + xr[lines[:, 1]])
        force_error = np.abs(F - load).max() / scale
        moment_error = np.abs(M - np.cross(x[tip] - mid, load)).max() / (scale * length)
        # The reference-line closed form, within the bound its neglect of u allows.
        reference_error = np.abs(M - np.cross(xr[tip] - mid_r, load)).max()
        bound = 2.0 * np.linalg.norm(u, axis=1).max() * scale + tolerance * scale * length
        worst_force = max(worst_force, force_error)
        worst_moment = max(worst_moment, moment_error)
        worst_reference = max(worst_reference, reference_error / bound)
        failed |= force_error > tolerance or moment_error > tolerance or reference_error > bound
    print(f"vtk_equilibrium: {len(files)} files: force off λP by {worst_force:.3g} of λ|P|, "
          f"moment off (x_tip − x) × λP by {worst_moment:.3g} of λ|P| L, off λP (L − x) by "
          f"{worst_reference:.3g} of its bound 2 max|u| λ|P|")
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
