"""Write the shipped mesh files of ``meshes/`` from their parameters.

Run ``python meshes/make_meshes.py`` (from anywhere); it rewrites every file below.
Each file holds dimensionless coordinates in the units its use reads them in:

* ``korovchinsky_patch.vtu`` - the graded triangle patch of the Korovchinsky strip
  problem (``bearing_fem.physics.thermal.strip_mesh``) in units of the strip half-width
  a: radius 50 a, 48 cells across the strip; ``thermal.strip_source(..., mesh=...)``.
* ``point_elastic_129.vtu`` - the default grid of an elastic point contact: 129 x 129
  uniform nodes on x/a in [-4.5, 1.5], y/b in [-3, 3] (Hertz semi-axes).
* ``point_rigid_graded_161.vtu`` - the default grid of a rigid point contact with Reynolds
  cavitation: 161 x 161 sinh-graded nodes on x in [-30, 8], y in [-30, 30] hydrodynamic
  lengths sqrt(2 r h0) (``bearing_fem.contacts.point_grid.graded_coordinates``).
* ``line_elastic_1801.vtu`` - the default grid of the line map's M = 100, L = 10 case:
  1801 uniform nodes on x/b in [-4.5, 1.5] (Hertz half-widths).
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
from skfem import MeshLine

from bearing_fem.contacts.point_grid import graded_coordinates
from bearing_fem.mesh import tensor_mesh, write_mesh
from bearing_fem.physics.thermal import strip_mesh

HERE = Path(__file__).resolve().parent


def main(outdir: str | Path = HERE) -> dict[str, Path]:
    """Write every mesh file; return their paths."""
    out = Path(outdir)
    files = {}
    patch, _, _ = strip_mesh(1.0, 50.0, 48)
    files["korovchinsky_patch"] = write_mesh(patch, out / "korovchinsky_patch.vtu")
    files["point_elastic_129"] = write_mesh(
        tensor_mesh(np.linspace(-4.5, 1.5, 129), np.linspace(-3.0, 3.0, 129)),
        out / "point_elastic_129.vtu")
    files["point_rigid_graded_161"] = write_mesh(
        tensor_mesh(graded_coordinates(-30.0, 8.0, 161, 1.0, stretch=1.5),
                    graded_coordinates(-30.0, 30.0, 161, 1.0, stretch=1.5)),
        out / "point_rigid_graded_161.vtu")
    files["line_elastic_1801"] = write_mesh(MeshLine(np.linspace(-4.5, 1.5, 1801)),
                                            out / "line_elastic_1801.vtu")
    return files


if __name__ == "__main__":
    for name, path in main().items():
        print(f"{name}: {path}")
