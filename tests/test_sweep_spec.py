"""Sweep files: axes, zipped axes, dotted keys, validation messages (no solving)."""
from __future__ import annotations

import copy

import numpy as np
import pytest
import tomli_w

from bearing_fem.errors import SceneError
from bearing_fem.sweep import Case, SweepSpec, scene_hash
from bearing_fem.sweep.spec import set_dotted
from bearing_fem.scene import Scene

BASE = {
    "title": "rigid cylinder",
    "contact": {"kind": "line", "rx": 0.01},
    "lubricant": {"viscosity": 0.01, "piezo": 2e-8},
    "kinematics": {"u1": 1.0, "u2": 1.0},
    "load": {"gap": 1e-6},
    "model": {"elasticity": "rigid"},
    "mesh": {"nodes": 101},
}


def write_sweep(tmp_path, sweep: dict, base: dict | None = BASE, name="sweep.toml"):
    if base is not None:
        (tmp_path / "base.toml").write_text(tomli_w.dumps(base), encoding="utf-8")
    path = tmp_path / name
    path.write_text(tomli_w.dumps(sweep), encoding="utf-8")
    return path


def test_product_linspace_logspace_and_zip(tmp_path):
    path = write_sweep(tmp_path, {
        "sweep": {"scene": "base.toml"},
        "axes": {"load.gap": [1e-6, 2e-6], "kinematics.u1": {"logspace": [-1.0, 1.0, 3]}},
        "zip": {"kinematics.u2": "kinematics.u1",
                "lubricant.viscosity": {"with": "kinematics.u1",
                                        "linspace": [0.01, 0.03, 3]}},
    })
    spec = SweepSpec.from_toml(path)
    assert len(spec) == 6 and spec.kind == "scene"
    assert spec.keys == ["load.gap", "kinematics.u1", "kinematics.u2", "lubricant.viscosity"]
    params = spec.params()
    # first axis outermost; zipped keys follow the leader's index
    assert [p["load.gap"] for p in params] == [1e-6] * 3 + [2e-6] * 3
    np.testing.assert_allclose([p["kinematics.u1"] for p in params[:3]], [0.1, 1.0, 10.0],
                               rtol=1e-15, err_msg="logspace = numpy's 10**linspace")
    assert all(p["kinematics.u2"] == p["kinematics.u1"] for p in params)
    np.testing.assert_allclose([p["lubricant.viscosity"] for p in params[:3]],
                               [0.01, 0.02, 0.03], rtol=1e-15)
    cases = spec.cases()
    assert [c.scene.kinematics.u2 for c in cases] == [p["kinematics.u2"] for p in params]
    assert cases[4].scene.load.gap == 2e-6
    assert cases[4].scene.lubricant.viscosity == pytest.approx(0.02, rel=1e-15)
    assert len({c.hash for c in cases}) == 6
    # the base file is untouched by the cases
    assert spec.base["load"]["gap"] == 1e-6


def test_unquoted_dotted_keys_and_new_tables(tmp_path):
    # an unquoted TOML dotted key arrives as nested tables; a swept key may add a table
    text = ('[sweep]\nscene = "base.toml"\n[axes]\nload.gap = [1e-6]\n'
            'mesh.x_range = [[-10.0, 2.0], [-20.0, 2.0]]\n'
            '"traction.model" = ["newtonian", "eyring"]\n')
    (tmp_path / "base.toml").write_text(tomli_w.dumps(BASE), encoding="utf-8")
    (tmp_path / "s.toml").write_text(text, encoding="utf-8")
    spec = SweepSpec.from_toml(tmp_path / "s.toml")
    assert spec.keys == ["load.gap", "mesh.x_range", "traction.model"]
    cases = spec.cases()
    assert len(cases) == 4
    assert cases[3].scene.mesh.x_range == (-20.0, 2.0)
    assert cases[3].scene.traction.model == "eyring"


def test_hash_is_of_the_resolved_scene():
    a = Scene.from_dict(BASE)
    d = copy.deepcopy(BASE)
    d["kinematics"] = {"u1": 1, "u2": 1}  # integers validate to the same floats
    assert scene_hash(a) == scene_hash(Scene.from_dict(d))
    d["load"] = {"gap": 1.1e-6}
    assert scene_hash(a) != scene_hash(Scene.from_dict(d))
    assert len(scene_hash(a)) == 64


def test_inline_base_table_and_defaults():
    spec = SweepSpec.from_dict({"sweep": {"scene": BASE, "workers": 2, "files": "summary",
                                          "retry_failed": True},
                                "axes": {}})
    assert len(spec) == 1 and spec.workers == 2 and spec.files == "summary"
    assert spec.retry_failed is True
    (case,) = spec.cases()
    assert case.params == {} and case.scene == Scene.from_dict(BASE)


def test_set_dotted_refuses_a_path_through_a_value():
    d = copy.deepcopy(BASE)
    with pytest.raises(SceneError, match=r"'load.gap' is 1e-06 in the base file, not a table"):
        set_dotted(d, "load.gap.x", 1.0)


@pytest.mark.parametrize("sweep, match", [
    ({"sweep": {}}, "missing sweep.scene"),
    ({"axes": {}}, r"missing \[sweep\] table"),
    ({"sweep": {"scene": "base.toml", "sceen": 1}}, r"unknown key\(s\) sweep.sceen; known"),
    ({"sweep": {"scene": "base.toml"}, "axis": {}}, r"unknown table\(s\) or key\(s\) 'axis'"),
    ({"sweep": {"scene": "missing.toml"}}, r"cannot read base file .*missing.toml"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"force": [1.0]}},
     r"'force': a swept key must be a dotted key"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": []}},
     r"axis 'load.gap': values must be a non-empty list"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": {"linspace": [1e-6, 2e-6]}}},
     r"linspace must be \[start, stop, n\]"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": {"linspace": [1e-6, 2e-6, 2.5]}}},
     r"linspace n must be an integer"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": {"logspace": [-6, 2e3, 3]}}},
     r"logspace exponents must lie in \[-300, 300\]"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": {"range": [1, 2, 3]}}},
     r"exactly one of linspace"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": [1e-6]},
      "zip": {"kinematics.u2": "kinematics.u1"}},
     r"the leader 'kinematics.u1' is not an axis"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": [1e-6, 2e-6]},
      "zip": {"kinematics.u2": {"with": "load.gap", "values": [1.0]}}},
     r"1 values for 2 values of its leader 'load.gap'"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": [1e-6]},
      "zip": {"load.gap": "load.gap"}}, r"'load.gap' is both an axis and a zipped key"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": [1e-6],
                                                "load": {"gap": [2e-6, 3e-6]}}},
     r"\[axes\] gives 'load.gap' twice \(quoted"),
    ({"sweep": {"scene": "base.toml"}, "axes": {"load.gap": [1e-6, 2e-6]},
      "zip": {"kinematics.u2": "load.gap", "kinematics": {"u2": "load.gap"}}},
     r"\[zip\] gives 'kinematics.u2' twice"),
    ({"sweep": {"scene": "base.toml", "workers": 0}}, r"sweep.workers must be an integer"),
    ({"sweep": {"scene": "base.toml", "files": "fields"}}, r"sweep.files must be one of"),
    ({"sweep": {"scene": "base.toml", "retry_failed": "yes"}},
     r"sweep.retry_failed must be true or false"),
])
def test_bad_sweep_files_name_the_key(tmp_path, sweep, match):
    path = write_sweep(tmp_path, sweep)
    with pytest.raises(SceneError, match=match) as err:
        SweepSpec.from_toml(path)
    if "missing.toml" not in match:
        assert str(err.value).startswith(str(path)), f"names the sweep file: {err.value}"


def test_bad_case_value_names_key_value_and_unit(tmp_path):
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"lubricant.viscosity": [0.01, -0.02]}})
    spec = SweepSpec.from_toml(path)  # the axis itself is well formed
    with pytest.raises(SceneError) as err:
        spec.cases()
    text = str(err.value)
    assert "case 1 (lubricant.viscosity = -0.02)" in text, text
    assert "lubricant.viscosity must lie in" in text and "Pa s, got -0.02" in text, text


def test_unknown_scene_key_is_named(tmp_path):
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.forse": [1.0]}})
    with pytest.raises(SceneError, match=r"load.forse = 1.0\): unknown key\(s\) load.forse"):
        SweepSpec.from_toml(path).cases()


def test_duplicate_cases_are_refused(tmp_path):
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"},
                                  "axes": {"load.gap": [1e-6, 1.0e-6]}})
    with pytest.raises(SceneError, match=r"cases 0 \(load.gap = 1e-06\) and 1 .* resolve to "
                                         "the same scene"):
        SweepSpec.from_toml(path).cases()


def test_case_parameter_names_may_not_shadow_store_columns():
    scene = Scene.from_dict(BASE)
    assert Case({"M": 20, "L": 5}, scene).params == {"M": 20, "L": 5}
    for bad in ("status", "hash", "error_estimate.h_central", ""):
        with pytest.raises(SceneError, match="parameter name"):
            Case({bad: 1}, scene)
    with pytest.raises(SceneError, match="must be a Scene or a Bearing"):
        Case({}, BASE)


def test_not_toml_and_bom(tmp_path):
    (tmp_path / "bad.toml").write_text("[sweep\nscene=", encoding="utf-8")
    with pytest.raises(SceneError, match="is not valid TOML"):
        SweepSpec.from_toml(tmp_path / "bad.toml")
    path = write_sweep(tmp_path, {"sweep": {"scene": "base.toml"}})
    path.write_text("\ufeff" + path.read_text(encoding="utf-8"), encoding="utf-8")
    assert len(SweepSpec.from_toml(path)) == 1
