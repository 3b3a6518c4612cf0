"""The primal-dual active set of the rigid linear path (Reynolds cavitation as an
obstacle problem) from a first guess of the cavitated set."""
import numpy as np
import pytest
import scipy.sparse as sp

import bearing_fem as bf
from bearing_fem.contacts.linear import active_set_solve


def _journal_like(n: int = 400):
    """1D Reynolds operator of a converging-diverging gap h = 1 + x^2 on [-4, 4] (P1,
    unit coefficients): A q = f with f the weak wedge term, zero end values."""
    x = np.linspace(-4.0, 4.0, n)
    dx = x[1] - x[0]
    hm = 1.0 + (0.5 * (x[1:] + x[:-1])) ** 2
    k = hm**3 / dx
    main = np.zeros(n)
    main[:-1] += k
    main[1:] += k
    a = sp.diags([main, -k, -k], [0, 1, -1], format="csr")
    f = np.zeros(n)
    f[:-1] -= hm
    f[1:] += hm
    return a, f, np.arange(1, n - 1)


@pytest.mark.parametrize("guess", ["coarse", "all", "none", "random"])
def test_any_first_guess_gives_the_cold_solution(guess):
    a, f, free = _journal_like()
    n = f.size
    q0, s0, act0 = active_set_solve(a, f, np.zeros(n), free, "reynolds")
    assert act0.any() and (~act0[free]).any(), "the test needs a cavitated region"
    rng = np.random.default_rng(1)
    start = {"coarse": np.repeat(act0[::2], 2)[:n], "all": np.ones(n, bool),
             "none": np.zeros(n, bool), "random": rng.random(n) < 0.5}[guess]
    q, s, act = active_set_solve(a, f, np.zeros(n), free, "reynolds", active=start)
    np.testing.assert_allclose(q, q0, atol=1e-12 * np.max(np.abs(q0)),
                               err_msg="the discrete obstacle problem has one solution")
    assert np.array_equal(act, act0)
    if guess == "coarse":
        assert s < s0, (s, s0)


def test_a_guess_that_does_not_settle_restarts_cold():
    a, f, free = _journal_like()
    n = f.size
    q0, s0, _ = active_set_solve(a, f, np.zeros(n), free, "reynolds")
    q, s, _ = active_set_solve(a, f, np.zeros(n), free, "reynolds", max_sweeps=2,
                               active=np.ones(n, bool))
    # two sweeps from "all dry" do not settle; the cold restart gets as far as it can
    # in its own two sweeps, and both runs count
    assert s == 2 + min(s0, 2)


def test_point_linear_path_solves_coarse_to_fine():
    """A rigid ball with Reynolds cavitation: the 161^2 solve starts from the 81^2 set
    (3 instead of 20 solves measured), with the same film numbers as from scratch."""
    s = bf.Scene.from_dict({
        "contact": {"kind": "point", "rx": 0.01, "ry": 0.01},
        "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
        "kinematics": {"u1": 1.0, "u2": 1.0}, "load": {"gap": 1e-6},
        "mesh": {"nodes": [81, 81]},
        "model": {"elasticity": "rigid", "cavitation": "reynolds"}})
    r = bf.solve(s)
    assert r.status == "linear"
    from bearing_fem.contacts.point import PointModel
    model = PointModel(s, far_field=True)   # as solve_point builds it
    cold_status, cold, _, cold_solves = model.linear(model.levels()[-1])
    assert cold_status == "linear"
    assert r.linear_solves < cold_solves, (r.linear_solves, cold_solves)
    for key in ("load", "p_max", "h_min", "friction_force"):
        np.testing.assert_allclose(r.quantities[key], cold.quantities[key], rtol=1e-12,
                                   err_msg=f"{key}: warm and cold active sets differ")
