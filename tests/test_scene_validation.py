"""Bad input: every scene field rejected with a message naming its field, value and unit.

Each case mutates a valid base scene and must give

* through the command line, ``bearing-fem solve``: exit code 2, the field name on
  stderr, no traceback, no output written;
* through the API, :meth:`Scene.from_dict`: a :class:`SceneError` naming the field.

``test_every_field_has_a_case`` fails when a scene field is added without a case here.
Sections that the installed ``bearing_fem.scene`` does not (yet) define are skipped.
"""
from __future__ import annotations

import copy
from dataclasses import fields

import pytest

from bearing_fem import cli
from bearing_fem import scene as scene_module
from bearing_fem.errors import SceneError
from bearing_fem.io import scene_to_toml
from bearing_fem.scene import Scene

DELETE = object()

#: A valid line scene that touches every line-contact section (rigid with a gap: the
#: positive control solves in a fraction of a second).
LINE = {
    "title": "validation base",
    "contact": {"kind": "line", "rx": 0.01, "length": 0.02},
    "materials": {"e1": 2.1e11, "nu1": 0.3, "e2": 2.1e11, "nu2": 0.3},
    "lubricant": {"viscosity": 0.05, "piezo": 2e-8, "viscosity_law": "barus",
                  "density": "incompressible"},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 1e-6},
    "model": {"elasticity": "rigid", "cavitation": "reynolds", "thermal": "none"},
    "mesh": {"nodes": 401, "x_range": [-50.0, 5.0]},
    "solver": {"tolerance": 1e-8, "max_iterations": 50, "continuation": True},
}
#: A valid elastic point scene (used for the point-only fields; never solved here).
POINT = {
    "contact": {"kind": "point", "rx": 0.0127, "ry": 0.0127},
    "materials": {"reduced_modulus": 2.3e11},
    "lubricant": {"viscosity": 0.04, "piezo": 2.2e-8},
    "kinematics": {"u1": 1.0, "u2": 1.0},
    "load": {"force": 30.0},
    "mesh": {"nodes": [65, 65], "x_range": [-4.5, 1.5], "y_range": [-3.0, 3.0]},
}
THERMAL = {"oil_temperature": 40.0, "exponent": 2.5}
TRACTION = {"model": "eyring"}
#: A valid squeeze series: a rigid ball with a vibrating gap.
SQUEEZE = {
    "contact": {"kind": "point", "rx": 0.00635, "ry": 0.00635},
    "lubricant": {"viscosity": 0.0106, "piezo": 2e-8},
    "kinematics": {"u1": 2.0, "u2": 2.0},
    "load": {"gap": 2e-7},
    "model": {"elasticity": "rigid", "cavitation": "none"},
    "transient": {"kind": "squeeze", "amplitude": 0.3, "angular_frequency": 2e4, "steps": 8,
                  "periods": 1, "scheme": "bdf2"},
}


def _line_elastic() -> dict:
    d = copy.deepcopy(LINE)
    d["load"] = {"force": 2e5}
    d["model"]["elasticity"] = "half-space"
    d.pop("mesh")
    return d


def _case(id_, changes, *expect, base="line"):
    """A case: ``changes`` maps "section.key" (or "section", or "title") to a value or
    DELETE; ``expect`` are substrings the message must contain (the field name first)."""
    return pytest.param(base, changes, expect, id=id_)


NAN, INF = float("nan"), float("inf")

CASES = [
    # --- top level -------------------------------------------------------------------
    _case("title-type", {"title": 5}, "title"),
    _case("unknown-section", {"frobnicate": {"a": 1}}, "frobnicate", "known"),
    _case("unknown-top-key", {"titel": "typo"}, "titel", "known"),
    *[_case(f"missing-[{s}]", {s: DELETE}, f"[{s}]")
      for s in ("contact", "lubricant", "kinematics", "load")],
    _case("section-not-table", {"contact": 5}, "[contact]"),
    *[_case(f"unknown-key-{s}", {f"{s}.colour": 1}, f"{s}.colour", "known keys")
      for s in ("contact", "materials", "lubricant", "kinematics", "load", "model", "mesh",
                "solver")],
    # --- contact ---------------------------------------------------------------------
    _case("contact.kind-value", {"contact.kind": "circle"}, "contact.kind", "'line'"),
    _case("contact.kind-type", {"contact.kind": 5}, "contact.kind"),
    _case("contact.rx-sign", {"contact.rx": -0.01}, "contact.rx", "-0.01", "m"),
    _case("contact.rx-zero", {"contact.rx": 0.0}, "contact.rx"),
    _case("contact.rx-type", {"contact.rx": "ten mm"}, "contact.rx", "ten mm"),
    _case("contact.rx-bool", {"contact.rx": True}, "contact.rx"),
    _case("contact.rx-nan", {"contact.rx": NAN}, "contact.rx", "finite"),
    _case("contact.rx-inf", {"contact.rx": INF}, "contact.rx", "finite"),
    _case("contact.rx-missing", {"contact.rx": DELETE}, "contact.rx"),
    _case("contact.ry-on-line", {"contact.ry": 0.01}, "contact.ry", "point"),
    _case("contact.ry-missing-point", {"contact.ry": DELETE}, "contact.ry", base="point"),
    _case("contact.ry-sign", {"contact.ry": -1.0}, "contact.ry", "m", base="point"),
    _case("contact.ry-type", {"contact.ry": "wide"}, "contact.ry", base="point"),
    _case("contact.length-sign", {"contact.length": -0.02}, "contact.length", "m"),
    _case("contact.length-type", {"contact.length": "long"}, "contact.length"),
    _case("contact.length-on-point", {"contact.length": 0.02}, "contact.length",
          base="point"),
    # --- materials -------------------------------------------------------------------
    *[_case(f"materials.{k}-sign", {f"materials.{k}": -2.1e11}, f"materials.{k}", "Pa")
      for k in ("e1", "e2")],
    *[_case(f"materials.{k}-type", {f"materials.{k}": "steel"}, f"materials.{k}")
      for k in ("e1", "e2")],
    *[_case(f"materials.{k}-missing", {f"materials.{k}": DELETE}, f"materials.{k}")
      for k in ("e1", "nu1", "e2", "nu2")],
    *[_case(f"materials.{k}-range-high", {f"materials.{k}": 0.6}, f"materials.{k}", "0.6")
      for k in ("nu1", "nu2")],
    *[_case(f"materials.{k}-range-low", {f"materials.{k}": -1.0}, f"materials.{k}")
      for k in ("nu1", "nu2")],
    *[_case(f"materials.{k}-type", {f"materials.{k}": "0.3"}, f"materials.{k}")
      for k in ("nu1", "nu2")],
    _case("materials.reduced_modulus-and-pair", {"materials.reduced_modulus": 2.3e11},
          "reduced_modulus"),
    _case("materials.reduced_modulus-sign", {"materials.reduced_modulus": -1.0},
          "materials.reduced_modulus", "Pa", base="point"),
    _case("materials.reduced_modulus-type", {"materials.reduced_modulus": "hard"},
          "materials.reduced_modulus", base="point"),
    _case("materials-missing-elastic", {"materials": DELETE}, "materials",
          base="line-elastic"),
    # --- lubricant -------------------------------------------------------------------
    _case("lubricant.viscosity-sign", {"lubricant.viscosity": -0.01},
          "lubricant.viscosity", "-0.01", "Pa s"),
    _case("lubricant.viscosity-zero", {"lubricant.viscosity": 0.0}, "lubricant.viscosity"),
    _case("lubricant.viscosity-type", {"lubricant.viscosity": "thick"},
          "lubricant.viscosity"),
    _case("lubricant.viscosity-missing", {"lubricant.viscosity": DELETE},
          "lubricant.viscosity"),
    _case("lubricant.viscosity-roelands-range",
          {"lubricant.viscosity_law": "roelands", "lubricant.viscosity": 1e5},
          "lubricant.viscosity", "Roelands"),
    _case("lubricant.piezo-sign", {"lubricant.piezo": -2e-8}, "lubricant.piezo", "1/Pa"),
    _case("lubricant.piezo-range", {"lubricant.piezo": 2e-5}, "lubricant.piezo", "1/Pa"),
    _case("lubricant.piezo-type", {"lubricant.piezo": "high"}, "lubricant.piezo"),
    _case("lubricant.viscosity_law-value", {"lubricant.viscosity_law": "vogel"},
          "lubricant.viscosity_law", "'barus'"),
    _case("lubricant.viscosity_law-type", {"lubricant.viscosity_law": 1},
          "lubricant.viscosity_law"),
    _case("lubricant.density-value", {"lubricant.density": "tait"}, "lubricant.density",
          "'dowson-higginson'"),
    _case("lubricant.density-type", {"lubricant.density": 870.0}, "lubricant.density"),
    # --- kinematics ------------------------------------------------------------------
    *[_case(f"kinematics.{k}-type", {f"kinematics.{k}": "fast"}, f"kinematics.{k}", "m/s")
      for k in ("u1", "u2")],
    *[_case(f"kinematics.{k}-missing", {f"kinematics.{k}": DELETE}, f"kinematics.{k}")
      for k in ("u1", "u2")],
    *[_case(f"kinematics.{k}-nan", {f"kinematics.{k}": NAN}, f"kinematics.{k}")
      for k in ("u1", "u2")],
    _case("kinematics-mean-speed-sign", {"kinematics.u1": -1.0, "kinematics.u2": -1.0},
          "kinematics", "mean speed", "m/s"),
    # zero speeds: the message gives the documented least speed, not "> 0"
    _case("kinematics-mean-speed-zero", {"kinematics.u1": 0.0, "kinematics.u2": 0.0},
          "kinematics", "mean speed", "must be at least 1e-06 m/s"),
    # --- load ------------------------------------------------------------------------
    _case("load.force-sign", {"load.force": -1.0, "load.gap": DELETE}, "load.force", "N"),
    _case("load.force-type", {"load.force": "heavy", "load.gap": DELETE}, "load.force"),
    _case("load.gap-sign", {"load.gap": -1e-7}, "load.gap", "m"),
    _case("load.gap-type", {"load.gap": "thin"}, "load.gap"),
    _case("load-both", {"load.force": 1e5}, "load.force", "load.gap"),
    _case("load-neither", {"load.gap": DELETE}, "load.force", "load.gap"),
    # --- model -----------------------------------------------------------------------
    _case("model.elasticity-value", {"model.elasticity": "elastic"}, "model.elasticity",
          "'half-space'"),
    _case("model.elasticity-type", {"model.elasticity": 1}, "model.elasticity"),
    _case("model.elasticity-local-needs-force", {"model.elasticity": "local"},
          "model.elasticity", "load.force"),
    _case("model.elasticity-local-on-point", {"model.elasticity": "local"},
          "model.elasticity", base="point"),
    _case("model.cavitation-value", {"model.cavitation": "jfo"}, "model.cavitation",
          "'reynolds'"),
    _case("model.thermal-value", {"model.thermal": "full"}, "model.thermal", "'patch'"),
    _case("model.thermal-patch-needs-section", {"model.thermal": "patch"}, "model.thermal",
          "[thermal]", base="line-elastic"),
    # --- mesh ------------------------------------------------------------------------
    _case("mesh.nodes-small", {"mesh.nodes": 5}, "mesh.nodes", "9"),
    _case("mesh.nodes-large", {"mesh.nodes": 30001}, "mesh.nodes", "20001"),
    _case("mesh.nodes-float", {"mesh.nodes": 400.5}, "mesh.nodes"),
    _case("mesh.nodes-type", {"mesh.nodes": "many"}, "mesh.nodes"),
    _case("mesh.nodes-three", {"mesh.nodes": [9, 9, 9]}, "mesh.nodes"),
    _case("mesh.nodes-two-on-line", {"mesh.nodes": [401, 401]}, "mesh.nodes", "line"),
    _case("mesh.nodes-one-on-point", {"mesh.nodes": 65}, "mesh.nodes", "point",
          base="point"),
    _case("mesh.x_range-order", {"mesh.x_range": [1.0, 2.0]}, "mesh.x_range"),
    _case("mesh.x_range-length", {"mesh.x_range": [-4.5]}, "mesh.x_range"),
    _case("mesh.x_range-type", {"mesh.x_range": ["a", 1.5]}, "mesh.x_range"),
    _case("mesh.x_range-inf", {"mesh.x_range": [-INF, 1.5]}, "mesh.x_range"),
    _case("mesh.y_range-on-line", {"mesh.y_range": [-3.0, 3.0]}, "mesh.y_range", "point"),
    _case("mesh.y_range-order", {"mesh.y_range": [0.0, 3.0]}, "mesh.y_range",
          base="point"),
    _case("mesh.y_range-type", {"mesh.y_range": "wide"}, "mesh.y_range", base="point"),
    # elastic scenes with a load: ranges in Hertz half-widths must contain [-1, 1]
    _case("mesh.x_range-in-metres", {"mesh.x_range": [-0.0005, 0.0003]}, "mesh.x_range",
          "[-0.0005, 0.0003]", "Hertz half-width", "[-1, 1]", base="point"),
    _case("mesh.y_range-inside-hertz", {"mesh.y_range": [-0.9, 0.9]}, "mesh.y_range",
          "[-0.9, 0.9]", "Hertz zone", base="point"),
    _case("mesh.grading-value", {"mesh.grading": "graded"}, "mesh.grading", "'outlet'"),
    _case("mesh.grading-type", {"mesh.grading": 1}, "mesh.grading"),
    _case("mesh.grading-outlet-on-point", {"mesh.grading": "outlet"}, "mesh.grading",
          "contact.kind = 'point'", base="point"),
    _case("mesh.target_error-percent", {"mesh.target_error": 5.0}, "mesh.target_error",
          "[0.001, 0.5]", "0.05 is 5 %"),
    _case("mesh.target_error-type", {"mesh.target_error": "5 %"}, "mesh.target_error"),
    # --- solver ----------------------------------------------------------------------
    _case("solver.tolerance-sign", {"solver.tolerance": -1e-8}, "solver.tolerance"),
    _case("solver.tolerance-zero", {"solver.tolerance": 0.0}, "solver.tolerance"),
    _case("solver.tolerance-range", {"solver.tolerance": 0.5}, "solver.tolerance", "0.1"),
    _case("solver.tolerance-type", {"solver.tolerance": "tight"}, "solver.tolerance"),
    _case("solver.max_iterations-zero", {"solver.max_iterations": 0},
          "solver.max_iterations"),
    _case("solver.max_iterations-large", {"solver.max_iterations": 10**6},
          "solver.max_iterations"),
    _case("solver.max_iterations-float", {"solver.max_iterations": 10.5},
          "solver.max_iterations"),
    _case("solver.max_iterations-bool", {"solver.max_iterations": True},
          "solver.max_iterations"),
    _case("solver.continuation-type", {"solver.continuation": "yes"},
          "solver.continuation"),
    _case("solver.continuation-int", {"solver.continuation": 1}, "solver.continuation"),
    _case("solver.iteration_budget-zero", {"solver.iteration_budget": 0},
          "solver.iteration_budget"),
    _case("solver.iteration_budget-float", {"solver.iteration_budget": 40.5},
          "solver.iteration_budget"),
    _case("solver.time_limit-negative", {"solver.time_limit": -1.0}, "solver.time_limit", " s"),
    _case("solver.time_limit-type", {"solver.time_limit": "soon"}, "solver.time_limit"),
    # --- thermal (model.thermal = "patch") -------------------------------------------
    _case("unknown-key-thermal", {"thermal.colour": 1}, "thermal.colour", base="thermal"),
    *[_case(f"thermal.{k}-missing", {f"thermal.{k}": DELETE}, f"thermal.{k}",
            base="thermal") for k in ("oil_temperature", "exponent")],
    _case("thermal.oil_temperature-sign", {"thermal.oil_temperature": -10.0},
          "thermal.oil_temperature", "deg C", base="thermal"),
    _case("thermal.oil_temperature-type", {"thermal.oil_temperature": "warm"},
          "thermal.oil_temperature", base="thermal"),
    _case("thermal.exponent-sign", {"thermal.exponent": 0.0}, "thermal.exponent",
          base="thermal"),
    _case("thermal.temperature_law-value", {"thermal.temperature_law": "vogel"},
          "thermal.temperature_law", "'prokofiev'", base="thermal"),
    _case("thermal.reference_temperature-sign", {"thermal.reference_temperature": 0.0},
          "thermal.reference_temperature", "deg C", base="thermal"),
    _case("thermal.reference_viscosity-sign", {"thermal.reference_viscosity": -0.1},
          "thermal.reference_viscosity", "Pa s", base="thermal"),
    _case("thermal.piezo_temperatures-alone", {"thermal.piezo_temperatures": [40.0]},
          "thermal.piezo_temperatures", base="thermal"),
    _case("thermal.piezo_temperatures-order",
          {"thermal.piezo_temperatures": [80.0, 40.0], "thermal.piezo_values": [1e-8, 2e-8]},
          "thermal.piezo_temperatures", "ascending", base="thermal"),
    _case("thermal.piezo_values-alone", {"thermal.piezo_values": [2e-8]},
          "thermal.piezo_values", base="thermal"),
    _case("thermal.piezo_values-range",
          {"thermal.piezo_temperatures": [40.0], "thermal.piezo_values": [2e-5]},
          "thermal.piezo_values", "1/Pa", base="thermal"),
    _case("thermal.piezo_values-length",
          {"thermal.piezo_temperatures": [40.0, 80.0], "thermal.piezo_values": [2e-8]},
          "thermal.piezo_values", base="thermal"),
    *[_case(f"thermal.{k}-sign", {f"thermal.{k}": -1.0}, f"thermal.{k}", unit,
            base="thermal")
      for k, unit in (("conductivity", "W/(m K)"), ("density", "kg/m^3"),
                      ("heat_capacity", "J/(kg K)"), ("conductivity2", "W/(m K)"),
                      ("density2", "kg/m^3"), ("heat_capacity2", "J/(kg K)"))],
    _case("thermal.conductivity-type", {"thermal.conductivity": "steel"},
          "thermal.conductivity", base="thermal"),
    _case("thermal.source_model-value", {"thermal.source_model": "exact"},
          "thermal.source_model", "'jaeger'", base="thermal"),
    _case("thermal.contact_temperature-value", {"thermal.contact_temperature": "min"},
          "thermal.contact_temperature", "'mean'", base="thermal"),
    _case("thermal.max_iterations-zero", {"thermal.max_iterations": 0},
          "thermal.max_iterations", base="thermal"),
    _case("thermal.max_iterations-float", {"thermal.max_iterations": 2.5},
          "thermal.max_iterations", base="thermal"),
    _case("thermal.tolerance-sign", {"thermal.tolerance": 0.0}, "thermal.tolerance", "K",
          base="thermal"),
    _case("thermal.relaxation-range", {"thermal.relaxation": 1.5}, "thermal.relaxation",
          base="thermal"),
    _case("thermal.max_temperature_rise-sign", {"thermal.max_temperature_rise": 0.0},
          "thermal.max_temperature_rise", "K", base="thermal"),
    _case("thermal.relaxation-sign", {"thermal.relaxation": -0.5}, "thermal.relaxation",
          base="thermal"),
    # --- traction --------------------------------------------------------------------
    _case("unknown-key-traction", {"traction.colour": 1}, "traction.colour",
          base="traction"),
    _case("traction.model-value", {"traction.model": "power"}, "traction.model",
          "'eyring'", base="traction"),
    _case("traction.eyring_stress-sign", {"traction.eyring_stress": 0.0},
          "traction.eyring_stress", "Pa", base="traction"),
    _case("traction.limiting_shear_stress-sign", {"traction.limiting_shear_stress": -1.0},
          "traction.limiting_shear_stress", "Pa", base="traction"),
    _case("traction.limiting_slope-sign", {"traction.limiting_slope": -0.1},
          "traction.limiting_slope", base="traction"),
    _case("traction.limiting-both-zero",
          {"traction.limiting_shear_stress": 0.0, "traction.limiting_slope": 0.0},
          "limiting_shear_stress", "limiting_slope", base="traction"),
]

#: Finite extremes that passed validation once and crashed (or overflowed) in the solve,
#: and unit slips that cannot be computed: each bound is in docs/scenes.md ("Ranges").
EXTREMES = [
    _case("contact.rx-subnormal", {"contact.rx": 5e-324}, "contact.rx", "5e-324", "m"),
    _case("contact.rx-huge", {"contact.rx": 1e308}, "contact.rx", "1e+308", "m"),
    _case("contact.ry-huge", {"contact.ry": 1e308}, "contact.ry", "m", base="point"),
    _case("contact.ry-ratio", {"contact.rx": 1e-6, "contact.ry": 1.0}, "contact.ry / contact.rx",
          "line contact", base="point"),
    _case("contact.length-huge", {"contact.length": 1e308}, "contact.length", "m"),
    _case("materials.e1-in-GPa", {"materials.e1": 208.0}, "materials.e1", "208", "Pa"),
    _case("materials.reduced_modulus-small", {"materials.reduced_modulus": 1e5},
          "materials.reduced_modulus", "Pa", base="point"),
    _case("materials-poisson-near-minus-one",
          {"materials.nu1": -0.99999999999999, "materials.nu2": -0.99999999999999,
           "materials.e1": 1e29, "materials.e2": 1e29}, "materials", "E'", "Pa"),
    _case("lubricant.viscosity-huge", {"lubricant.viscosity": 1e308}, "lubricant.viscosity",
          "Pa s"),
    _case("lubricant.viscosity-tiny", {"lubricant.viscosity": 1e-300}, "lubricant.viscosity",
          "Pa s"),
    _case("lubricant.viscosity-roelands-low",
          {"lubricant.viscosity_law": "roelands", "lubricant.viscosity": 1e-5},
          "lubricant.viscosity", "Roelands"),
    # (Barus half-space scenes are overflow-safe and accepted; Kodnir's local model is not)
    _case("lubricant.piezo-overflow", {"lubricant.piezo": 1e-6, "load.force": 2e7,
                                       "model.elasticity": "local"},
          "lubricant.piezo", "1/Pa", "double precision", base="line-elastic"),
    _case("kinematics-huge-speeds", {"kinematics.u1": 1e308, "kinematics.u2": 1e308},
          "kinematics.u1", "m/s"),
    _case("kinematics-mean-speed-tiny", {"kinematics.u1": 1e-9, "kinematics.u2": 1e-9},
          "kinematics", "mean speed", "m/s"),
    _case("load.force-huge", {"load.force": 1e308}, "load.force", "N"),
    _case("load.force-401-digits", {"load.force": 10**400, "load.gap": DELETE}, "load.force",
          "401 chars",
          "floating-point range"),
    _case("load.force-hertz-width", {"load.force": 1e9}, "load.force", "a_x",
          "contact.rx", "Hertz", base="point"),
    _case("load.force-line-hertz-width", {"load.force": 1e11}, "load.force", "N/m",
          "Hertz half-width b", base="line-elastic"),
    _case("load.gap-subnormal", {"load.gap": 5e-324}, "load.gap", "m"),
    _case("load.gap-huge", {"load.gap": 1.0}, "load.gap", "m"),
    _case("title-nul", {"title": "roller\x00"}, "title", "U+0000"),
    _case("title-escape", {"title": "roller\x1b[31m"}, "title", "control character"),
    _case("title-newline", {"title": "two\nlines"}, "title", "one line"),
    _case("title-long", {"title": "t" * 1_000_000}, "title", "1000000"),
    _case("mesh.x_range-huge", {"mesh.x_range": [-1e308, 1.5]}, "mesh.x_range"),
    _case("mesh.x_range-401-digits", {"mesh.x_range": [-(10**400), 1.5]}, "mesh.x_range",
          "chars"),
    _case("solver.time_limit-huge", {"solver.time_limit": 1e308}, "solver.time_limit", "s"),
    _case("thermal.oil_temperature-huge", {"thermal.oil_temperature": 1e308},
          "thermal.oil_temperature", "deg C", base="thermal"),
    _case("thermal.exponent-huge", {"thermal.exponent": 100.0}, "thermal.exponent",
          base="thermal"),
    _case("thermal.conductivity-subnormal", {"thermal.conductivity": 5e-324},
          "thermal.conductivity", "W/(m K)", base="thermal"),
    _case("thermal.piezo_values-401-digits",
          {"thermal.piezo_temperatures": [40.0], "thermal.piezo_values": [10**400]},
          "thermal.piezo_values", "chars", base="thermal"),
    _case("thermal-section-without-patch", {"model.thermal": "none"}, "[thermal]",
          "model.thermal", base="thermal"),
    _case("thermal-patch-on-point",
          {"model.thermal": "patch", "thermal": dict(THERMAL)}, "model.thermal",
          "line contacts only", base="point"),
    _case("thermal-patch-standing-surface", {"kinematics.u2": 0.0}, "model.thermal",
          "non-zero", "u2=0.0", base="thermal"),
    _case("traction.eyring_stress-subnormal", {"traction.eyring_stress": 5e-324},
          "traction.eyring_stress", "Pa", base="traction"),
    _case("traction.limiting_slope-above-1", {"traction.limiting_slope": 2.0},
          "traction.limiting_slope", "friction coefficient", base="traction"),
    _case("mesh.file-missing-file", {"mesh.nodes": DELETE, "mesh.x_range": DELETE,
                                     "mesh.file": "no/such/grid.vtu"}, "mesh.file",
          "does not exist"),
    _case("mesh.file-type", {"mesh.nodes": DELETE, "mesh.x_range": DELETE, "mesh.file": 5},
          "mesh.file"),
    _case("mesh.file-with-nodes", {"mesh.file": "grid.vtu"}, "mesh.file", "mesh.nodes"),
    # --- transient (squeeze series) ----------------------------------------------------
    _case("transient.kind-value", {"transient.kind": "impact"}, "transient.kind", "squeeze",
          base="squeeze"),
    _case("transient.amplitude-one", {"transient.amplitude": 1.0}, "transient.amplitude",
          "[0, 1)", base="squeeze"),
    _case("transient.amplitude-missing", {"transient.amplitude": DELETE},
          "transient.amplitude", base="squeeze"),
    _case("transient.angular_frequency-sign", {"transient.angular_frequency": -5.0},
          "transient.angular_frequency", "rad/s", base="squeeze"),
    _case("transient.steps-one", {"transient.steps": 1}, "transient.steps", base="squeeze"),
    _case("transient.periods-float", {"transient.periods": 1.5}, "transient.periods",
          base="squeeze"),
    _case("transient.scheme-value", {"transient.scheme": "rk4"}, "transient.scheme",
          base="squeeze"),
    _case("unknown-key-transient", {"transient.colour": 1}, "transient.colour", "known keys",
          base="squeeze"),
    _case("transient-under-load", {"load": {"force": 30.0}}, "[transient]", "load.gap",
          base="squeeze"),
    _case("transient-rigid-roelands", {"lubricant.viscosity_law": "roelands"}, "rigid",
          "Barus", base="squeeze"),
]
CASES += EXTREMES


def _base(name: str) -> dict:
    if name == "line":
        return copy.deepcopy(LINE)
    if name == "point":
        return copy.deepcopy(POINT)
    if name == "line-elastic":
        return _line_elastic()
    if name == "squeeze":
        return copy.deepcopy(SQUEEZE)
    if name in ("thermal", "traction"):
        if name not in scene_module._SECTIONS:
            pytest.skip(f"[{name}] is not a section of the installed bearing_fem.scene")
        d = _line_elastic()
        if name == "thermal":
            d["model"]["thermal"] = "patch"
            d["thermal"] = dict(THERMAL)
        else:
            d["traction"] = dict(TRACTION)
        return d
    raise AssertionError(name)


def _apply(data: dict, changes: dict) -> dict:
    for path, value in changes.items():
        section, _, key = path.partition(".")
        if not key:
            if value is DELETE:
                data.pop(section, None)
            else:
                data[section] = value
        elif value is DELETE:
            data[section].pop(key, None)
        else:
            data.setdefault(section, {})[key] = value
    return data


@pytest.mark.parametrize("base", ["line", "point", "line-elastic", "thermal", "traction",
                                  "squeeze"])
def test_bases_are_valid(base):
    """Positive control: without a change, every base scene validates."""
    Scene.from_dict(_base(base))


def test_numpy_numbers_are_numbers():
    """Values from np.linspace / np.arange (np.float32, np.int64, ...) are accepted as the
    numbers they hold and stored as plain Python numbers (they were refused: 'must be a
    number in Pa s, got np.float32(0.05)'); a numpy bool is still no number."""
    import numpy as np

    from bearing_fem.scene import Lubricant, MeshSpec

    data = _base("point")
    data["lubricant"]["viscosity"] = np.float32(0.04)
    data["kinematics"]["u1"] = np.int64(1)
    data["mesh"] = {"nodes": [np.int64(65), np.int32(65)],
                    "x_range": [np.float64(-20.0), np.int64(5)]}
    scene = Scene.from_dict(data)
    assert type(scene.lubricant.viscosity) is float and type(scene.kinematics.u1) is float
    assert scene.mesh.nodes == (65, 65) and all(type(n) is int for n in scene.mesh.nodes)
    assert scene.mesh.x_range == (-20.0, 5.0)
    assert Scene.from_toml_string(scene_to_toml(scene)) == scene, "round trip"
    assert type(Lubricant(viscosity=np.float32(0.05)).viscosity) is float
    assert MeshSpec(nodes=np.int64(401)).nodes == 401
    data["mesh"] = {"nodes": [np.bool_(True), 65]}
    with pytest.raises(SceneError, match="mesh.nodes"):
        Scene.from_dict(data)


def test_line_base_solves_with_exit_0(tmp_path):
    """Positive control through the command line (a cheap rigid linear solve)."""
    path = tmp_path / "ok.toml"
    path.write_text(scene_to_toml(LINE), encoding="utf-8")
    assert cli.main(["solve", str(path), "--out", str(tmp_path / "out")]) == 0


@pytest.mark.parametrize("base,changes,expect", CASES)
def test_from_dict_rejects(base, changes, expect):
    data = _apply(_base(base), changes)
    with pytest.raises(SceneError) as info:
        Scene.from_dict(data)
    for text in expect:
        assert text in str(info.value), f"{text!r} missing from: {info.value}"


@pytest.mark.parametrize("base,changes,expect", CASES)
def test_cli_rejects_with_exit_2(base, changes, expect, tmp_path, capsys):
    data = _apply(_base(base), changes)
    path = tmp_path / "scene.toml"
    path.write_text(scene_to_toml(data), encoding="utf-8")
    out = tmp_path / "out"
    assert cli.main(["solve", str(path), "--out", str(out)]) == 2
    captured = capsys.readouterr()
    for text in expect:
        assert text in captured.err, f"{text!r} missing from stderr: {captured.err}"
    assert "Traceback" not in captured.err
    assert not out.exists(), "invalid input must be rejected before any output"


@pytest.mark.parametrize("text,expect", [
    ("[contact\nkind = 'line'\n", "not valid TOML"),
    ("[contact]\nrx = 0.01\nrx = 0.02\n", "not valid TOML"),
    ("[lubricant]\nviscosity = \n", "not valid TOML"),
    ("title = 'unterminated\n", "not valid TOML"),
    ("title = " + "[" * 100_000 + "]" * 100_000 + "\n", "nested too deeply"),
    ("title = " + "{a=" * 5000 + "1" + "}" * 5000 + "\n", "nested too deeply"),
], ids=["open-table", "duplicate-key", "missing-value", "open-string", "deep-array",
        "deep-table"])
def test_cli_broken_toml(tmp_path, capsys, text, expect):
    path = tmp_path / "broken.toml"
    path.write_text(text, encoding="utf-8")
    assert cli.main(["solve", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert expect in err and "broken.toml" in err and "Traceback" not in err


def test_cli_unreadable_files(tmp_path, capsys):
    assert cli.main(["solve", str(tmp_path / "missing.toml"), "--out", str(tmp_path)]) == 2
    assert "missing.toml" in capsys.readouterr().err
    assert cli.main(["solve", str(tmp_path), "--out", str(tmp_path / "o")]) == 2  # a dir
    assert "cannot read" in capsys.readouterr().err
    binary = tmp_path / "binary.toml"
    binary.write_bytes(b"\xff\xfe\x00garbage")
    assert cli.main(["solve", str(binary), "--out", str(tmp_path / "o")]) == 2
    err = capsys.readouterr().err
    assert "invalid input" in err and "binary.toml' is not UTF-8 text" in err, \
        "a scene file that is not UTF-8 is named in a SceneError message"


def test_from_dict_rejects_non_mapping():
    with pytest.raises(SceneError, match="table"):
        Scene.from_dict([("contact", {})])


def test_every_field_has_a_case():
    """Every field of every section of the installed scene module has a case above."""
    covered = set()
    for case in CASES:
        _, changes, _ = case.values
        covered.update(changes)
    missing = []
    for section, klass in scene_module._SECTIONS.items():
        for f in fields(klass):
            if f.name.startswith("_"):
                continue
            if f"{section}.{f.name}" not in covered:
                missing.append(f"{section}.{f.name}")
        if f"{section}.colour" not in covered:
            missing.append(f"{section}.<unknown key>")
    assert "title" in covered
    assert not missing, f"no validation case for: {', '.join(missing)}"


def test_messages_name_value_and_unit():
    """A sample of messages carries the offending value and the unit, not just the name."""
    with pytest.raises(SceneError) as info:
        Scene.from_dict(_apply(_base("line"), {"lubricant.viscosity": -0.01}))
    msg = str(info.value)
    assert "lubricant.viscosity" in msg and "-0.01" in msg and "Pa s" in msg
    with pytest.raises(SceneError) as info:
        Scene.from_dict(_apply(_base("line"), {"contact.rx": float("nan")}))
    assert "contact.rx" in str(info.value) and "nan" in str(info.value)


def test_long_values_are_echoed_short(tmp_path, capsys):
    """A 1 MB string, a 5000-digit integer and a 1 MB key give one short line each."""
    long_string = "x" * 1_000_000
    for changes, expect in (({"lubricant.viscosity": long_string}, "1000002 chars"),
                            ({"lubricant.viscosity": 10**5000}, "digits"),
                            ({"lubricant." + long_string: 1.0}, "characters"),
                            ({"contact.kind": long_string}, "chars")):
        data = _apply(_base("line"), changes)
        with pytest.raises(SceneError) as info:
            Scene.from_dict(data)
        msg = str(info.value)
        assert expect in msg and len(msg) < 400, msg[:500]
    path = tmp_path / "long.toml"
    path.write_text(scene_to_toml(_apply(_base("line"), {"lubricant.viscosity": long_string})),
                    encoding="utf-8")
    assert cli.main(["solve", str(path), "--out", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert len(err) < 400 and "lubricant.viscosity" in err, err[:500]


def test_byte_order_mark_is_accepted(tmp_path):
    """Some editors start UTF-8 files with a byte-order mark: the scene reads as without."""
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + scene_to_toml(LINE).encode("utf-8"))
    assert Scene.from_toml(path) == Scene.from_dict(LINE)
    assert cli.main(["solve", str(path), "--out", str(tmp_path / "out")]) == 0


def test_bounds_are_inclusive_where_documented():
    """Positive controls at the documented ends of the ranges (docs/scenes.md, "Ranges")."""
    from bearing_fem import scene as sc

    ok = [{"contact.rx": sc.LENGTH_RANGE[0]}, {"contact.rx": sc.LENGTH_RANGE[1]},
          {"lubricant.viscosity": sc.VISCOSITY_RANGE[0]},
          {"lubricant.viscosity": sc.VISCOSITY_RANGE[1]},
          {"kinematics.u1": sc.MAX_SPEED, "kinematics.u2": -sc.MAX_SPEED + 1.0},
          {"load.gap": sc.GAP_RANGE[0]}, {"load.gap": sc.GAP_RANGE[1]},
          {"materials.e1": sc.MODULUS_RANGE[0]}, {"title": "t" * sc.MAX_TITLE},
          {"title": "Rolle auf Innenring, \u00d8 20 mm \u2013 \u03b7 = 0.05 Pa s"}]
    for changes in ok:
        Scene.from_dict(_apply(_base("line"), changes))
