"""Point/elliptical contacts (bearing_fem.point): Kapitsa oracles, convergence, status.

The rigid oracles (PHYSICS.md 5.1) are imposed as Dirichlet data on the finite domain,
so only the discretisation error is measured.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from bearing_fem import analytic as an
from bearing_fem.point import PointGrid, solve_point
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                               Model, Scene, SolverSpec)

ETA0 = 0.01      # Pa s
U_M = 1.0        # m/s
H0 = 1e-7        # m


def rigid_scene(rx: float, ry: float, *, piezo: float = 0.0, cavitation: str = "none",
                nodes=None, x_range=None, y_range=None) -> Scene:
    return Scene(contact=Contact(kind="point", rx=rx, ry=ry),
                 lubricant=Lubricant(viscosity=ETA0, piezo=piezo),
                 kinematics=Kinematics(u1=U_M, u2=U_M), load=Load(gap=H0),
                 model=Model(elasticity="rigid", cavitation=cavitation),
                 mesh=MeshSpec(nodes=nodes, x_range=x_range, y_range=y_range))


def exact_fn(rx, ry, dh0dt, piezo=0.0):
    a, b = 1 / (2 * rx), 1 / (2 * ry)
    return lambda x, y: an.kapitsa_point_pressure(x, y, H0, a, b, ETA0, U_M, dh0dt, piezo)


def q_max(rx, ry, dh0dt):
    return float(an.kapitsa_point_max_reduced(H0, 1 / (2 * rx), 1 / (2 * ry), ETA0, U_M, dh0dt))


CASES = [  # (rx, ry, dh0/dt): wedge, squeeze, both; circular and elliptical
    (0.01, 0.01, 0.0), (0.01, 0.01, -2e-4), (0.01, 0.04, 0.0), (0.01, 0.04, -1e-4),
    (0.02, 0.005, -1e-4),
]


@pytest.mark.parametrize("rx, ry, dh0dt", CASES)
@pytest.mark.parametrize("ratio", [0.0, 0.9])
def test_kapitsa_peak_default_mesh(rx, ry, dh0dt, ratio):
    qm = q_max(rx, ry, dh0dt)
    piezo = ratio / qm
    res = solve_point(rigid_scene(rx, ry, piezo=piezo), boundary_pressure=exact_fn(
        rx, ry, dh0dt, piezo), squeeze_velocity=dh0dt)
    assert res.status == "linear", res.message
    assert res.pressure.shape == (res.y.size, res.x.size)
    p_exact = float(an.barus_from_reduced(qm, piezo))
    np.testing.assert_allclose(res.quantities["p_max"], p_exact, rtol=5e-3,
                               err_msg="p_max within 0.5% of Kapitsa on the default graded "
                                       "161^2 mesh (issue acceptance; the Barus case at "
                                       "alpha q_max = 0.9 amplifies q errors 10x)")
    assert np.all(np.isfinite(res.pressure))
    # the rigid film is the prescribed gap plus the geometry
    assert res.quantities["h_central"] == pytest.approx(H0, rel=1e-12)
    assert res.quantities["h_min"] >= H0 * (1 - 1e-12)


def _l2_error(res, exact) -> float:
    grid = PointGrid.tensor(res.x, res.y)
    ops = grid.ops
    xq, yq = ops.points
    err = ops.value @ res.pressure.ravel() - exact(xq, yq)
    return math.sqrt(ops.integrate(err**2)) / math.sqrt(ops.integrate(exact(xq, yq) ** 2))


@pytest.mark.parametrize("rx, ry, dh0dt, ratio", [(0.01, 0.01, -1e-4, 0.0),
                                                  (0.01, 0.04, 0.0, 0.5)])
def test_kapitsa_l2_convergence_order(rx, ry, dh0dt, ratio):
    piezo = ratio / q_max(rx, ry, dh0dt)
    exact = exact_fn(rx, ry, dh0dt, piezo)
    hs, errs = [], []
    for n in (17, 33, 65):
        res = solve_point(rigid_scene(rx, ry, piezo=piezo, nodes=(n, n), x_range=(-3.0, 3.0),
                                      y_range=(-3.0, 3.0)),
                          boundary_pressure=exact, squeeze_velocity=dh0dt)
        assert res.success, res.message
        hs.append(res.x[1] - res.x[0])
        errs.append(_l2_error(res, exact))
    order = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert order >= 1.8, (f"observed L2 order {order:.2f} < 1.8 (bilinear elements: 2 in "
                          f"theory); errors {errs} at spacings {hs}")


def test_beyond_existence_is_no_solution():
    rx = ry = 0.01
    piezo = 1.2 / q_max(rx, ry, 0.0)
    res = solve_point(rigid_scene(rx, ry, piezo=piezo, nodes=(61, 61)))
    assert res.status == "no_solution" and not res.success
    assert "alpha*q_max" in res.message
    assert np.all(np.isfinite(res.pressure)), "fields hold q, never NaN"


def test_reynolds_cavitation_rigid():
    rx, ry = 0.01, 0.02
    res = solve_point(rigid_scene(rx, ry, cavitation="reynolds", nodes=(61, 61)))
    assert res.status == "linear", res.message
    assert np.min(res.pressure) >= 0.0, "Reynolds cavitation: p >= 0"
    assert res.quantities["load"] > 0.0
    # the cavitated (p = 0) zone lies downstream of the centre
    p = res.pressure
    j0 = int(np.argmin(np.abs(res.y)))
    zero_x = res.x[(p[j0] <= 0.0)]
    assert np.any(zero_x > 0.0)
    assert np.isfinite(res.quantities["friction_force"])
    assert res.quantities["heat_power"] > 0.0


def test_bad_input():
    scene = rigid_scene(0.01, 0.01, nodes=(21, 21))
    with pytest.raises(ValueError, match="squeeze_velocity"):
        solve_point(scene, squeeze_velocity=float("nan"))
    with pytest.raises(ValueError, match="boundary_pressure"):
        solve_point(scene, boundary_pressure=np.zeros(7))
