"""Sliding contacts: the friction coefficient of the traction models lies in the range of
lubricated rolling contacts, and the summary names the model (line and point contacts,
Barus and Roelands viscosity, slide-to-roll ratios 0.05, 0.5 and 2)."""
from __future__ import annotations

import math

import pytest

import bearing_fem as bf
from bearing_fem.scene import Scene

#: Friction coefficients of EHL contacts of mineral oils in the literature: about 0.005 to
#: 0.1 (traction curves of Johnson & Tevaarwerk 1977, Evans & Johnson 1986); the
#: acceptance range is set wider on both sides.
F_LOW, F_HIGH = 0.002, 0.15
SLIDE_TO_ROLL = (0.05, 0.5, 2.0)
MEAN_SPEED = 2.0  # m/s


def sliding_scene(kind: str, law: str, srr: float, traction: dict | None = None) -> Scene:
    """Steel contact at u_m = 2 m/s with slide-to-roll ``srr`` = (u1 - u2)/u_m: a line
    (R = 10 mm, 2e5 N/m, p_h ~ 0.9 GPa) or a ball (R = 10 mm, 200 N, p_h ~ 1.6 GPa) on a
    small grid, eta0 = 0.05 Pa s, alpha = 2e-8 1/Pa."""
    u1 = MEAN_SPEED * (1.0 + srr / 2.0)
    u2 = MEAN_SPEED * (1.0 - srr / 2.0)
    contact = {"kind": kind, "rx": 0.01} | ({"ry": 0.01} if kind == "point" else {})
    d = {"contact": contact, "materials": {"reduced_modulus": 2.2e11},
         "lubricant": {"viscosity": 0.05, "piezo": 2e-8, "viscosity_law": law},
         "kinematics": {"u1": u1, "u2": u2},
         "load": {"force": 2e5 if kind == "line" else 200.0},
         "mesh": {"nodes": 801 if kind == "line" else [65, 65]}}
    if traction is not None:
        d["traction"] = traction
    return Scene.from_dict(d)


@pytest.mark.parametrize("srr", SLIDE_TO_ROLL)
@pytest.mark.parametrize("law", ["barus", "roelands"])
@pytest.mark.parametrize("kind", ["line", "point"])
def test_default_and_eyring_traction_give_lubricated_friction(kind, law, srr):
    for traction, model in ((None, "eyring-limiting"),
                            ({"model": "eyring", "eyring_stress": 5e6}, "eyring")):
        r = bf.solve(sliding_scene(kind, law, srr, traction))
        assert r.success, r.message
        s = r.summary()
        f = s["friction_coefficient"]
        assert F_LOW <= f <= F_HIGH, (
            f"{kind} {law} srr {srr} {model}: friction coefficient {f:.4g} outside "
            f"[{F_LOW}, {F_HIGH}], the range of lubricated contacts")
        assert s["traction_model"] == model, "the summary names the traction model used"
        assert math.isfinite(s["heat_power"]) and s["heat_power"] > 0.0
        generic = [w for w in r.warnings if "generic" in w]
        assert bool(generic) == (traction is None), (
            "the generic default, and only it, is named in the warnings")


@pytest.mark.parametrize("kind", ["line", "point"])
def test_newtonian_sliding_request_is_flagged(kind):
    r = bf.solve(sliding_scene(kind, "barus", 0.5, {"model": "newtonian"}))
    assert r.success, r.message
    s = r.summary()
    assert s["traction_model"] == "newtonian"
    assert any("Newtonian traction gives an unphysical friction coefficient" in w
               for w in r.warnings), r.warnings
    f = s.get("friction_coefficient")
    assert f is None or f > 0.2, "the warning is given where the coefficient exceeds 0.2"


def test_outlet_position_ignores_pressures_at_the_solver_tolerance():
    # Reynolds outlet at x_c = 0.5037 (between nodes): p = c (x_c - x)^2 upstream, 0 after;
    # Newton leaves cavitated pressures of order 1e-8 p_max, which must not move the
    # outlet (nor the Couette friction, integrated up to it) by an element
    import numpy as np

    from bearing_fem.post import CAVITATED_PRESSURE_FRACTION, outlet_position_line

    x = np.linspace(-1.0, 1.0, 201)
    xc = 0.5037
    p = 1e9 * np.clip(1.0 - x**2, 0.0, None) * np.where(x < xc, (xc - x) ** 2, 0.0)
    clean = outlet_position_line(x, p, "reynolds")
    assert abs(clean - xc) < 2e-3, f"sqrt(p) extrapolation to the boundary, got {clean}"
    noisy = p + np.where(x >= xc, 1e-8 * p.max(), 0.0)
    assert outlet_position_line(x, noisy, "reynolds") == clean, \
        "pressures at 1e-8 of the maximum count as cavitated"
    # a pressurised node above the threshold still counts (the boundary moves downstream)
    real = p.copy()
    k = int(np.argmax(x >= xc))
    real[k] = 100 * CAVITATED_PRESSURE_FRACTION * p.max()
    assert outlet_position_line(x, real, "reynolds") > clean
