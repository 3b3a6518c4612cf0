"""Seeded fuzz of the command line: does ``bearing-fem solve`` or ``bearing-fem bearing``
ever crash, write NaN, contradict itself, call an unphysical number a success, or overrun
its budget?

Question
    For a few hundred generated scenes -- structural garbage (wrong types, unknown keys,
    missing sections, broken TOML, binary files), extreme values, sliding line and point
    contacts, thermal line contacts, point contacts with a traction model, rigid
    prescribed-gap contacts on both sides of Kapitsa's existence limit, line contacts
    on outlet-graded grids (``mesh.grading = "outlet"``) and contacts held to a
    ``mesh.target_error`` (solved again on finer grids) -- does every run
    of ``bearing-fem solve SCENE --out DIR`` end in an orderly way? And for bearing files
    generated from the five shipped examples -- mutations (a number scaled by 0, -1,
    1e-3 .. 1e6 or set to an extreme, a value of a wrong type, a string, a boolean,
    ``nan``/``inf``, a huge integer, a key missing, an unknown key or section, an optional
    key added), every number of the examples and the optional keys in turn at an extreme
    value, realistic variants that should solve (loads, speeds, oil temperatures,
    clearances, rows, contact angles, tapered rows with and without axial load, crowned
    and logarithmic rollers with few slices, the centrifugal model, the thermal patch)
    and structural garbage (broken TOML, a contact scene, an empty or binary file) -- does
    every run of ``bearing-fem bearing FILE --out DIR --no-figures`` end in an orderly way?

Scene
    Each case is a TOML file generated from a seed (:func:`generate`). Every generated
    scene that can be solved carries ``[solver] time_limit`` and ``iteration_budget``.
    Each case runs ``bearing_fem.cli.main(["solve", file, "--out", dir])`` in its own
    forked process (stdout and stderr captured at the file-descriptor level, a hard
    timeout well above the stated time limit), two at a time. Bearing cases run
    ``cli.main(["bearing", file, "--out", dir, "--no-figures"])`` the same way; every
    solvable one carries coarse contact grids (``[mesh] point_nodes`` 33..65 or
    ``line_nodes`` 201..401) and ``[solver] time_limit`` (0.5 or 1 s) and
    ``iteration_budget``, which apply to each contact scene.

Checks (each failure is a *violation*, listed with its case)
    * ``traceback``: an exit code other than 0, 2 or 3, or "Traceback" on stderr;
    * ``raw-warning``: a Python warning (e.g. numpy ``RuntimeWarning``) printed raw;
    * ``nonfinite``: NaN or inf anywhere in summary.json (strict JSON);
    * ``exit-vs-success``: exit 0 without ``success = true``, exit 3 without
      ``success = false``, or exit 2 with files written;
    * ``long-message``: an exit-2 message longer than one line of 600 characters;
    * ``negative-film``, ``film-order``, ``negative-load``, ``friction>1``,
      ``negative-heat``: a successful summary with h_min or h_central < 0,
      h_min > h_central, load < 0, |friction_coefficient| > 1 or heat_power < 0;
    * ``budget-iterations``: more Newton iterations than ``solver.iteration_budget``
      (with ``mesh.target_error``: those of every grid, ``refinement.newton_iterations``);
    * ``budget-time``: a summary ``wall_time_s`` above 1.25 x ``solver.time_limit`` + 1 s
      (the limit is checked between Newton iterations, and post-processing follows the
      last one), or a process that had to be killed at its hard timeout.

    Bearing cases are checked the same way on ``bearing_summary.json``, the physical checks
    applied to every number of a successful summary (totals, elements, contacts, film
    formulas, empirical models; not the input echo ``bearing`` or the relative errors
    ``error_estimate``): ``negative-film``, ``negative-load``, ``negative-torque``,
    ``negative-heat`` (keys in :data:`BEARING_SIGNED_KEYS`), ``friction>1`` (any
    ``friction_coefficient``), ``film-order`` (h_min > h_central in one mapping);
    ``budget-iterations`` and ``budget-time`` per contact scene (a profiled roller's
    contact, which sums its slices, per slice), and ``budget-time`` also for the
    bearing's wall time above 1.25 x the limit x its distinct contact solves + 1 s.

Expected outcome
    Zero violations. The study returns the counts and writes ``cases.csv`` and
    ``cases.md`` (every case and its outcome) and ``violations/<case>.toml``, the
    reproducer of each violation, into ``outdir``.

Run: ``python studies/scene_fuzz.py OUTDIR [--quick] [--seed N] [--only CATEGORY ..]``.
"""

import argparse
import copy
import csv
import json
import math
import multiprocessing
import os
import random
import re
import shutil
import sys
import time
import traceback
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

#: Cases per category (full study, quick subset).
COUNTS = {
    "garbage": (70, 9),
    "extreme": (60, 8),
    "elastic": (30, 3),
    "sliding": (40, 4),
    "point-traction": (25, 3),
    "thermal": (30, 3),
    "rigid-gap": (45, 7),
    "outlet-grading": (20, 2),
    "bearing-mutation": (60, 5),
    "bearing-variant": (24, 3),
    "bearing-garbage": (10, 2),
    "bearing-extreme": (39, 1),
    "target-error": (20, 1),
}
#: Margin on a stated time limit: factor and seconds (see the module docstring).
TIME_FACTOR, TIME_SLACK = 1.25, 1.0
#: Hard timeout of one case [s] beyond its time limit (imports are shared by fork;
#: export and the error-estimate levels come after the last Newton iteration).
HARD_TIMEOUT = 60.0
#: Hard timeout of one bearing case [s] (its contacts share the per-contact time limit).
HARD_TIMEOUT_BEARING = 180.0
#: Longest exit-2 message [characters].
MAX_MESSAGE = 600
#: A Python warning as ``warnings.showwarning`` prints it: "file.py:12: RuntimeWarning: ..".
RAW_WARNING = re.compile(r"\.py:\d+: \w*Warning: ")


@dataclass
class Case:
    """One generated scene file."""

    name: str
    category: str
    description: str
    text: bytes
    time_limit: float | None = None
    iteration_budget: int | None = None
    command: str = "solve"


@dataclass
class Outcome:
    """What one run did and what it violated."""

    case: Case
    exit_code: int | None
    wall_s: float
    status: str = ""
    success: Any = None
    newton_iterations: int | None = None
    summary_wall_s: float | None = None
    time_ratio: float | None = None
    violations: list[str] = field(default_factory=list)
    stderr: str = ""


# ---------------------------------------------------------------------------------------
# scene generation
# ---------------------------------------------------------------------------------------
def _toml(data: dict) -> bytes:
    from bearing_fem.io import scene_to_toml

    return scene_to_toml(data).encode("utf-8")


def _loguniform(rng: random.Random, lo: float, hi: float) -> float:
    return math.exp(rng.uniform(math.log(lo), math.log(hi)))


def _budget(rng: random.Random, data: dict, quick: bool) -> dict:
    data.setdefault("solver", {})
    data["solver"]["time_limit"] = 3.0 if quick else rng.choice([2.0, 5.0, 10.0])
    data["solver"]["iteration_budget"] = rng.choice([30, 80, 200])
    return data


def line_elastic(rng: random.Random, quick: bool) -> dict:
    """A steel roller contact of moderate load, speed and viscosity."""
    return {
        "title": "fuzz line",
        "contact": {"kind": "line", "rx": rng.uniform(0.005, 0.05), "length": 0.02},
        "materials": {"e1": 2.1e11, "nu1": 0.3, "e2": 2.1e11, "nu2": 0.3},
        "lubricant": {"viscosity": _loguniform(rng, 0.005, 0.3),
                      "piezo": rng.uniform(1e-8, 2.5e-8),
                      "viscosity_law": rng.choice(["barus", "roelands"])},
        "kinematics": {"u1": 1.0, "u2": 1.0},
        "load": {"force": _loguniform(rng, 2e4, 1e6)},
        "model": {"elasticity": rng.choice(["half-space", "local"])},
        "mesh": {"nodes": rng.choice([201, 301] if quick else [201, 301, 401, 801])},
    }


def point_elastic(rng: random.Random, quick: bool) -> dict:
    """A steel ball (circular or elliptical) contact."""
    rx = rng.uniform(0.003, 0.02)
    n = rng.choice([33, 41] if quick else [33, 49, 65])
    return {
        "title": "fuzz point",
        "contact": {"kind": "point", "rx": rx, "ry": rx * rng.choice([1.0, 1.0, 2.0, 8.0])},
        "materials": {"reduced_modulus": 2.3e11},
        "lubricant": {"viscosity": _loguniform(rng, 0.01, 0.2),
                      "piezo": rng.uniform(1e-8, 2.5e-8)},
        "kinematics": {"u1": 1.0, "u2": 1.0},
        "load": {"force": _loguniform(rng, 2.0, 300.0)},
        "mesh": {"nodes": [n, n]},
    }


def _speeds(rng: random.Random, srr: float) -> dict:
    u_m = _loguniform(rng, 0.3, 5.0)
    return {"u1": u_m * (1.0 + srr / 2.0), "u2": u_m * (1.0 - srr / 2.0)}


def _traction(rng: random.Random) -> dict | None:
    model = rng.choice([None, "eyring", "limiting", "eyring-limiting", "newtonian"])
    if model is None:
        return None
    out: dict[str, Any] = {"model": model}
    if rng.random() < 0.5:
        out["eyring_stress"] = _loguniform(rng, 1e6, 2e7)
        out["limiting_shear_stress"] = rng.choice([0.0, 1e6, 5e6])
        out["limiting_slope"] = rng.uniform(0.02, 0.12)
    return out


def _add_traction(rng: random.Random, data: dict) -> str:
    """Give a scene a random ``[traction]`` section (or none); return the model's name."""
    traction = _traction(rng)
    if traction:
        data["traction"] = traction
    return traction["model"] if traction else "default"


def gen_elastic(rng: random.Random, quick: bool) -> tuple[str, dict]:
    data = (line_elastic if rng.random() < 0.6 else point_elastic)(rng, quick)
    return f"pure rolling {data['contact']['kind']}", data


def gen_sliding(rng: random.Random, quick: bool) -> tuple[str, dict]:
    data = (line_elastic if rng.random() < 0.5 else point_elastic)(rng, quick)
    srr = rng.choice([0.05, 0.5, 2.0])
    data["kinematics"] = _speeds(rng, srr)
    model = _add_traction(rng, data)
    return f"{data['contact']['kind']} SRR {srr:g}, traction {model}", data


def gen_point_traction(rng: random.Random, quick: bool) -> tuple[str, dict]:
    data = point_elastic(rng, quick)
    srr = rng.choice([0.05, 0.1, 0.5, 2.0])
    data["kinematics"] = _speeds(rng, srr)
    data["traction"] = _traction(rng) or {"model": "eyring"}
    return f"point SRR {srr:g}, traction {data['traction']['model']}", data


def gen_outlet_grading(rng: random.Random, quick: bool) -> tuple[str, dict]:
    """A half-space line contact on the grid refined at its outlet spike (the spike
    located by a uniform solve first: both count against the budget), sometimes
    sliding."""
    data = line_elastic(rng, quick)
    data["model"]["elasticity"] = "half-space"
    data["mesh"] = {"grading": "outlet", "nodes": rng.choice([201, 401, 801])}
    srr = rng.choice([0.0, 0.0, 0.3, 1.0])
    if srr:
        data["kinematics"] = _speeds(rng, srr)
        data["traction"] = {"model": "eyring-limiting"}
    return f"line outlet grading, SRR {srr:g}", data


def gen_thermal(rng: random.Random, quick: bool) -> tuple[str, dict]:
    data = line_elastic(rng, quick)
    data["mesh"]["nodes"] = rng.choice([201, 301])
    data["lubricant"]["viscosity_law"] = "barus"
    srr = rng.choice([0.0, 0.05, 0.3, 1.0])
    data["kinematics"] = _speeds(rng, srr)
    data["model"]["thermal"] = "patch"
    data["thermal"] = {"oil_temperature": rng.uniform(30.0, 110.0),
                       "exponent": rng.uniform(2.0, 3.5),
                       "source_model": rng.choice(["jaeger", "jaeger", "fe"]),
                       "contact_temperature": rng.choice(["mean", "max"]),
                       "max_iterations": rng.choice([1, 5, 30])}
    model = _add_traction(rng, data)
    return (f"thermal line SRR {srr:g}, {data['thermal']['source_model']}, traction "
            f"{model}"), data


def gen_rigid_gap(rng: random.Random, quick: bool) -> tuple[str, dict]:
    """Rigid Barus contacts with a prescribed gap, alpha q_max on both sides of 1."""
    from bearing_fem import analytic

    kind = rng.choice(["line", "line", "point"])
    cav = rng.choice(["none", "reynolds"])
    ratio = rng.choice([0.3, 0.8, 0.95, 0.99, 1.01, 1.1, 2.0, 5.0])
    rx, eta, u = rng.uniform(0.005, 0.03), _loguniform(rng, 0.01, 0.2), _loguniform(rng, 0.5, 5)
    h0 = _loguniform(rng, 3e-8, 2e-6)
    if kind == "line":
        q_max = (float(analytic.martin_max_reduced(h0, rx, eta, u)) if cav == "reynolds"
                 else float(analytic.kapitsa_line_max_reduced(h0, rx, eta, u)))
        contact = {"kind": "line", "rx": rx}
        mesh = {"nodes": rng.choice([401, 801])}
    else:
        ry = rx * rng.choice([1.0, 3.0])
        q_max = float(analytic.kapitsa_point_max_reduced(h0, 1 / (2 * rx), 1 / (2 * ry), eta, u))
        contact = {"kind": "point", "rx": rx, "ry": ry}
        n = rng.choice([41, 61])
        mesh = {"nodes": [n, n]}
    piezo = min(ratio / q_max, 1e-6)
    data = {"title": "fuzz rigid gap", "contact": contact,
            "lubricant": {"viscosity": eta, "piezo": piezo},
            "kinematics": {"u1": u, "u2": u}, "load": {"gap": h0},
            "model": {"elasticity": "rigid", "cavitation": cav}, "mesh": mesh}
    if rng.random() < 0.3:  # a load-controlled rigid contact instead (Martin estimate)
        data["load"] = {"force": _loguniform(rng, 1e2, 1e5)
                        if kind == "line" else _loguniform(rng, 0.1, 50.0)}
        return f"rigid {kind} {cav}, load-controlled", data
    note = "approximate (Kapitsa, no cavitation)" if kind == "point" and cav == "reynolds" else ""
    return f"rigid {kind} {cav}, alpha q_max = {alpha_q(piezo, q_max):.3g} {note}".strip(), data


def alpha_q(piezo: float, q_max: float) -> float:
    """alpha q_max of a generated rigid scene [-]."""
    return piezo * q_max


#: Numeric fields that extreme cases set (section, key).
NUMERIC_FIELDS = [("contact", "rx"), ("contact", "ry"), ("contact", "length"),
                  ("materials", "reduced_modulus"), ("lubricant", "viscosity"),
                  ("lubricant", "piezo"), ("kinematics", "u1"), ("kinematics", "u2"),
                  ("load", "force"), ("load", "gap"), ("solver", "tolerance"),
                  ("solver", "time_limit"), ("mesh", "x_range")]
EXTREMES = [0.0, -1.0, 5e-324, 1e-300, 1e-12, 1e-7, 1e-4, 1e3, 1e6, 1e9, 1e12, 1e300,
            1e308, -1e308, 10**400]


def gen_extreme(rng: random.Random, quick: bool) -> tuple[str, dict]:
    base = rng.choice([line_elastic, point_elastic])(rng, quick)
    if rng.random() < 0.3:
        base["model"] = {"elasticity": "rigid"}
        base["load"] = {"gap": 1e-6}
    section, key = rng.choice(NUMERIC_FIELDS)
    if rng.random() < 0.5:
        value: Any = rng.choice(EXTREMES)
    else:
        value = math.copysign(10.0 ** rng.uniform(-30, 30), rng.choice([1.0, 1.0, -1.0]))
    if key == "x_range":
        value = [-abs(value) if isinstance(value, float) else -value, 1.5]
    if section == "load":
        base["load"] = {key: value}
    else:
        base.setdefault(section, {})[key] = value
    if section == "contact" and key == "ry" and base["contact"]["kind"] == "line":
        base["contact"]["kind"] = "point"
        base["contact"].pop("length", None)
        base["mesh"] = {"nodes": [33, 33]}
    shown = value if not isinstance(value, int) or abs(value) < 1e30 else "10**400"
    return f"{section}.{key} = {shown}", base


GARBAGE_VALUES = ["text", True, [1.0, 2.0], {"a": 1}, -0.0, 10**400, "1e-3", [], ""]


def _garbage(rng: random.Random, quick: bool) -> tuple[str, bytes]:
    base = rng.choice([line_elastic, point_elastic])(rng, quick)
    choice = rng.randrange(15)
    if choice == 14:
        depth = rng.choice([1000, 100_000])
        return f"array nested {depth} deep", b"title = " + b"[" * depth + b"]" * depth
    if choice == 0:
        section = rng.choice(list(base))
        base.pop(section)
        return f"section [{section}] missing", _toml(base)
    if choice == 1:
        section = rng.choice([s for s in base if isinstance(base[s], dict)])
        key = rng.choice(list(base[section]))
        value = rng.choice(GARBAGE_VALUES)
        if isinstance(value, dict):  # an inline table: written by hand (not a scene value)
            base[section][key] = "__inline__"
            text = _toml(base).replace(b'"__inline__"', b"{ a = 1 }")
        else:
            base[section][key] = value
            text = _toml(base)
        return f"{section}.{key} of wrong type {type(value).__name__}", text
    if choice == 2:
        section = rng.choice([s for s in base if isinstance(base[s], dict)])
        base[section]["colour"] = "blue"
        return f"unknown key {section}.colour", _toml(base)
    if choice == 3:
        base["frobnicate"] = {"a": 1}
        return "unknown section [frobnicate]", _toml(base)
    text = _toml(base)
    if choice == 4:
        cut = rng.randrange(1, len(text))
        return f"truncated after {cut} bytes", text[:cut]
    if choice == 5:
        data = bytearray(text)
        for _ in range(rng.randint(1, 5)):
            data[rng.randrange(len(data))] = rng.choice(b"[]=\"'#\n\\{},.xyz0")
        return "corrupted bytes", bytes(data)
    if choice == 6:
        return "empty file", b""
    if choice == 7:
        return "binary garbage", bytes(rng.randrange(256) for _ in range(200))
    if choice == 8:
        return "UTF-8 byte-order mark (valid)", b"\xef\xbb\xbf" + text
    if choice == 9:
        base["title"] = "roller\x00" if rng.random() < 0.5 else "esc\x1b[31m red"
        return "control character in the title", _toml(base)
    if choice == 10:
        base["lubricant"]["viscosity"] = "x" * 100_000
        return "100 kB string value", _toml(base)
    if choice == 11:
        return "datetime value", text.replace(b"[lubricant]\n",
                                              b"[lubricant]\nviscosity_law = 1979-05-27\n", 1)
    if choice == 12:
        return "array of tables [[contact]]", text.replace(b"[contact]", b"[[contact]]", 1)
    base["thermal"] = {"oil_temperature": 60.0, "exponent": 2.9}
    return "[thermal] section without model.thermal = 'patch'", _toml(base)


def gen_target_error(rng: random.Random, quick: bool) -> tuple[str, dict]:
    """An elastic line or point contact with ``mesh.target_error``: solved again on finer
    grids, every solve within the one ``[solver]`` budget."""
    data = rng.choice([line_elastic, point_elastic])(rng, quick)
    data["mesh"]["target_error"] = _loguniform(rng, 0.002, 0.05)
    return (f"{data['contact']['kind']} target_error {data['mesh']['target_error']:.3g}",
            data)


GENERATORS: dict[str, Callable[[random.Random, bool], tuple[str, dict]]] = {
    "extreme": gen_extreme, "elastic": gen_elastic, "sliding": gen_sliding,
    "point-traction": gen_point_traction, "thermal": gen_thermal, "rigid-gap": gen_rigid_gap,
    "outlet-grading": gen_outlet_grading, "target-error": gen_target_error,
}


# ---------------------------------------------------------------------------------------
# bearing files (``bearing-fem bearing FILE --out DIR --no-figures``)
# ---------------------------------------------------------------------------------------
#: The shipped example bearings the bearing cases start from.
BEARING_EXAMPLES = ["6209", "7010-steel", "7010-hybrid", "nncf5040", "30205"]
#: Factors the mutations scale one number by.
BEARING_FACTORS = [0.0, -1.0, 1e-3, 1e-2, 0.1, 10.0, 1e3, 1e6]
#: Values of a wrong type or of no finite number for the mutations.
BEARING_ODD_VALUES: list[Any] = ["text", "1e-3", True, False, [1.0, 2.0], "__inline__",
                                 math.nan, math.inf, -math.inf, 10**400, 2**63]
#: Values far outside any range (as the scenes' EXTREMES).
BEARING_EXTREMES = [5e-324, 1e-300, 1e-20, 1e20, 1e300, -1e300]
#: Optional keys the shipped examples leave out, with a plausible value that a mutation
#: scales (or replaces by an extreme).
BEARING_OPTIONAL: dict[tuple[str, str], Any] = {
    ("bearing", "first_element_azimuth"): 20.0, ("bearing", "static_load_rating"): 2e4,
    ("materials", "element_density"): 7850.0, ("materials", "ring_modulus"): 2.08e11,
    ("materials", "element_poisson"): 0.3, ("model", "min_load_fraction"): 1e-3,
    ("model", "roughness"): 2e-7, ("empirical", "palmgren_f0"): 2.0,
    ("empirical", "palmgren_f1"): 5e-4, ("empirical", "friction_coefficient"): 0.003,
    ("empirical", "nikitin_flow_ratio"): 1.0, ("lubricant", "thermal_conductivity"): 0.13,
    ("lubricant", "specific_heat"): 2000.0, ("operation", "oil_temperature"): 60.0,
    ("mesh", "x_range"): [-4.5, 1.5], ("mesh", "y_range"): [-3.0, 3.0],
}


def example_bearing(name: str) -> dict:
    """A shipped example bearing as a nested dict (the TOML layout)."""
    from importlib import resources

    import tomllib

    text = (resources.files("bearing_fem") / "bearings" / f"{name}.toml").read_text(
        encoding="utf-8")
    return tomllib.loads(text)


def _is_ball(data: dict) -> bool:
    return str(data.get("bearing", {}).get("type", "")).endswith("ball")


def _bearing_budget(rng: random.Random, data: dict, quick: bool) -> dict:
    """Coarse contact grids and a per-contact solver budget: a few seconds a bearing."""
    mesh = data.setdefault("mesh", {})
    if _is_ball(data):
        n = rng.choice([33, 41] if quick else [33, 41, 49, 65])
        mesh["point_nodes"] = [n, n]
    else:
        mesh["line_nodes"] = rng.choice([201, 301] if quick else [201, 301, 401])
    data["solver"] = {"time_limit": rng.choice([0.5, 1.0]),
                      "iteration_budget": rng.choice([30, 80, 200])}
    return data


def _numeric_fields(data: dict) -> list[tuple[str, str]]:
    """(section, key) of every number of a bearing dict outside [mesh] and [solver]."""
    return [(sec, key) for sec, table in data.items() if isinstance(table, dict)
            and sec not in ("mesh", "solver") for key, v in table.items()
            if not isinstance(v, bool) and isinstance(v, (int, float, list))]


def _scaled(value: Any, factor: float) -> Any:
    if isinstance(value, list):
        return [_scaled(v, factor) for v in value]
    if isinstance(value, int) and float(factor).is_integer():
        return value * int(factor)
    return value * factor


def gen_bearing_mutation(rng: random.Random, quick: bool, index: int = 0) -> tuple[str, bytes, dict]:
    """One shipped example with one number scaled or set to an extreme (5e-324 ..
    1e300), one value of a wrong type (string, boolean, array, inline table, NaN, inf, a
    huge integer), an optional key added (plausible, scaled or extreme), a key missing or
    an unknown key or section."""
    name = rng.choice(BEARING_EXAMPLES)
    data = _bearing_budget(rng, example_bearing(name), quick)
    kind = rng.choices(["scale", "odd", "missing", "unknown", "extreme", "optional"],
                       weights=[5, 4, 2, 1, 2, 3])[0]
    if kind == "optional":
        (section, key), value = rng.choice(list(BEARING_OPTIONAL.items()))
        if rng.random() < 0.3:
            value = rng.choice(BEARING_EXTREMES)
            value = [-abs(value), 1.5] if isinstance(BEARING_OPTIONAL[section, key], list) \
                else value
        else:
            value = _scaled(value, rng.choice(BEARING_FACTORS + [1.0, 1.0]))
        data.setdefault(section, {})[key] = value
        return f"{name}: optional {section}.{key} = {value!r}", _toml(data), data
    if kind == "missing":
        section = rng.choice([s for s in data if isinstance(data[s], dict)])
        if rng.random() < 0.25:
            data.pop(section)
            return f"{name}: section [{section}] missing", _toml(data), data
        key = rng.choice(list(data[section]))
        data[section].pop(key)
        return f"{name}: {section}.{key} missing", _toml(data), data
    if kind == "unknown":
        if rng.random() < 0.5:
            section = rng.choice([s for s in data if isinstance(data[s], dict)])
            data[section]["colour"] = "blue"
            return f"{name}: unknown key {section}.colour", _toml(data), data
        data["frobnicate"] = {"a": 1}
        return f"{name}: unknown section [frobnicate]", _toml(data), data
    section, key = rng.choice(_numeric_fields(data))
    if kind == "extreme":
        value = rng.choice(BEARING_EXTREMES)
        data[section][key] = [value] * len(data[section][key]) \
            if isinstance(data[section][key], list) else value
        return f"{name}: {section}.{key} = {value!r}", _toml(data), data
    if kind == "scale":
        factor = rng.choice(BEARING_FACTORS)
        data[section][key] = _scaled(data[section][key], factor)
        return f"{name}: {section}.{key} x {factor:g}", _toml(data), data
    value = rng.choice(BEARING_ODD_VALUES)
    data[section][key] = value
    text = _toml(data)
    if value == "__inline__":
        text = text.replace(b'"__inline__"', b"{ a = 1 }")
        value = "{ a = 1 }"
    shown = "10**400" if isinstance(value, int) and value > 2**64 else repr(value)
    return f"{name}: {section}.{key} = {shown}", text, data


def gen_bearing_variant(rng: random.Random, quick: bool, index: int = 0) -> tuple[str, bytes, dict]:
    """A realistic bearing that should solve: a shipped example at another load, speed,
    oil temperature, clearance, number of rows or contact angle, a tapered bearing with
    and without axial load, crowned or logarithmic rollers with few slices, the
    centrifugal model, the thermal patch (roller bearings with the Prokofiev law)."""
    name = rng.choice(BEARING_EXAMPLES)
    data = example_bearing(name)
    b, op, model = data["bearing"], data["operation"], data.setdefault("model", {})
    kind = b["type"]
    notes = []
    choice = rng.choice(["load", "speed", "temperature", "clearance", "rows", "angle",
                         "profile", "centrifugal", "thermal"])
    if choice == "load":
        op["radial_load"] = round(op.get("radial_load", 0.0) * _loguniform(rng, 0.05, 3.0), 1)
        if kind in ("angular-contact-ball", "deep-groove-ball") and rng.random() < 0.5:
            op["axial_load"] = round(_loguniform(rng, 100.0, 3000.0), 1)
        notes.append(f"Fr {op['radial_load']:g} N, Fa {op.get('axial_load', 0.0):g} N")
    elif choice == "speed":
        op["inner_rpm"] = round(_loguniform(rng, 50.0, 20000.0 if _is_ball(data) else 5000.0))
        notes.append(f"{op['inner_rpm']:g} rpm")
    elif choice == "temperature":
        t = round(rng.uniform(20.0, 110.0), 1)
        op["oil_temperature"] = t
        lub = data["lubricant"]
        if lub.get("temperature_law") != "prokofiev":  # the viscosity at t: a Prokofiev oil
            eta = lub.pop("viscosity")
            lub.update({"temperature_law": "prokofiev", "reference_temperature": 60.0,
                        "reference_viscosity": eta, "exponent": 2.9})
        notes.append(f"oil at {t:g} C (Prokofiev)")
    elif choice == "clearance":
        if kind == "angular-contact-ball":
            b["contact_angle"] = round(rng.uniform(12.0, 30.0), 1)
            notes.append(f"contact angle {b['contact_angle']:g} deg")
        else:
            top = 20e-6 if _is_ball(data) else 0.04 * b["element_diameter"]
            b["radial_clearance"] = round(rng.uniform(0.0, top), 8)
            notes.append(f"c_r {b['radial_clearance']:g} m")
    elif choice == "rows" and not _is_ball(data):
        rows = rng.choice([1, 2, 4] if kind == "tapered-roller" else [1, 2, 3, 4])
        b["rows"] = rows
        if kind == "tapered-roller" and rows > 1 and rng.random() < 0.5:
            op["axial_load"] = 0.0
        if "width" in b:
            b["width"] = round(max(b["width"], 1.05 * rows * b["effective_length"]), 4)
        notes.append(f"{rows} rows, Fa {op.get('axial_load', 0.0):g} N")
    elif choice in ("angle", "rows"):
        if kind in ("angular-contact-ball", "tapered-roller"):
            beta = round(rng.uniform(10.0, 30.0 if kind == "tapered-roller" else 40.0), 1)
            b["contact_angle"] = beta
            if kind == "tapered-roller" and op.get("axial_load", 0.0) > 0.0:
                op["axial_load"] = round(1.6 * op["radial_load"] * math.tan(math.radians(beta)))
            notes.append(f"contact angle {beta:g} deg, Fa {op.get('axial_load', 0.0):g} N")
        else:  # the tapered example as a radially loaded pair
            data = example_bearing("30205")
            data["bearing"]["rows"] = 2
            data["bearing"]["width"] = 0.03
            data["operation"]["axial_load"] = rng.choice([0.0, 2000.0])
            name, notes = "30205", [f"2 rows, Fa {data['operation']['axial_load']:g} N"]
    elif choice == "profile" and not _is_ball(data):
        profile = rng.choice(["crowned", "crowned", "logarithmic"])
        b["profile"] = profile
        b["slices"] = rng.choice([3, 5, 7, 11])
        if profile == "crowned":
            b["crown_drop"] = round(_loguniform(rng, 1e-6, 0.005 * b["element_diameter"]), 8)
            if rng.random() < 0.5:
                b["flat_length"] = round(0.5 * b["effective_length"], 5)
        else:
            b["design_load"] = round(_loguniform(rng, 500.0, 50000.0))
        notes.append(f"{profile} rollers, {b['slices']} slices")
    elif choice in ("profile", "centrifugal"):
        model["centrifugal"] = True
        op["inner_rpm"] = round(op["inner_rpm"] * rng.choice([1.0, 2.0]))
        notes.append(f"centrifugal, {op['inner_rpm']:g} rpm")
    else:  # thermal patch: line contacts with the Prokofiev law
        if _is_ball(data) or data["lubricant"].get("temperature_law") != "prokofiev":
            data = example_bearing("nncf5040")
            name = "nncf5040"
        data.setdefault("model", {})["thermal"] = "patch"
        data["operation"]["oil_temperature"] = round(rng.uniform(30.0, 90.0), 1)
        data["thermal"] = {"max_iterations": rng.choice([3, 10]),
                           "source_model": rng.choice(["jaeger", "fe"])}
        notes.append(f"thermal patch at {data['operation']['oil_temperature']:g} C")
    if not data.get("model"):
        data.pop("model", None)
    data = _bearing_budget(rng, data, quick)
    return f"{name}: {', '.join(notes)}", _toml(data), data


def gen_bearing_garbage(rng: random.Random, quick: bool, index: int = 0) -> tuple[str, bytes, dict]:
    """Structural garbage given to ``bearing``: broken TOML, a contact scene, an empty or
    binary file, a byte-order mark (valid), ``[[bearing]]``, a missing ``[bearing]``."""
    name = rng.choice(BEARING_EXAMPLES)
    data = _bearing_budget(rng, example_bearing(name), quick)
    text = _toml(data)
    choice = rng.randrange(9)
    if choice == 0:
        cut = rng.randrange(1, len(text))
        return f"{name} truncated after {cut} bytes", text[:cut], {}
    if choice == 1:
        raw = bytearray(text)
        for _ in range(rng.randint(1, 5)):
            raw[rng.randrange(len(raw))] = rng.choice(b"[]=\"'#\n\\{},.xyz0")
        return f"{name} with corrupted bytes", bytes(raw), {}
    if choice == 2:
        scene = rng.choice([line_elastic, point_elastic])(rng, quick)
        return "a contact scene file", _toml(_budget(rng, scene, quick)), {}
    if choice == 3:
        return "empty file", b"", {}
    if choice == 4:
        return "binary garbage", bytes(rng.randrange(256) for _ in range(300)), {}
    if choice == 5:
        return f"{name} with a UTF-8 byte-order mark (valid)", b"\xef\xbb\xbf" + text, data
    if choice == 6:
        return f"{name} as an array of tables [[bearing]]", text.replace(
            b"[bearing]", b"[[bearing]]", 1), {}
    if choice == 7:
        data.pop("bearing")
        return f"{name} without [bearing]", _toml(data), {}
    return f"{name}, nested table [bearing.extra]", text + b"\n[bearing.extra]\na = 1\n", {}


def bearing_fields() -> list[tuple[str, str, list[str]]]:
    """(section, key, examples) of every number of the shipped examples and of the
    optional keys (:data:`BEARING_OPTIONAL`), with the examples it applies to."""
    out: dict[tuple[str, str], list[str]] = {}
    for name in BEARING_EXAMPLES:
        for field_ in _numeric_fields(example_bearing(name)):
            out.setdefault(field_, []).append(name)
    balls = [n for n in BEARING_EXAMPLES if _is_ball(example_bearing(n))]
    for field_ in BEARING_OPTIONAL:
        out.setdefault(field_, balls if field_ == ("mesh", "y_range") else BEARING_EXAMPLES)
    return [(sec, key, names) for (sec, key), names in out.items()]


def gen_bearing_extreme(rng: random.Random, quick: bool, index: int = 0
                        ) -> tuple[str, bytes, dict]:
    """Field ``index`` of :func:`bearing_fields` (every number once, in turn) set to an
    extreme value (:data:`BEARING_EXTREMES`) in an example that has it."""
    fields = bearing_fields()
    section, key, names = fields[index % len(fields)]
    name = rng.choice(names)
    data = _bearing_budget(rng, example_bearing(name), quick)
    value = rng.choice(BEARING_EXTREMES)
    old = data.get(section, {}).get(key, BEARING_OPTIONAL.get((section, key)))
    if key in ("x_range", "y_range"):
        new: Any = [-abs(value), 1.5] if rng.random() < 0.5 else [-4.5, abs(value)]
    elif isinstance(old, list):
        new = [value] * len(old)
    else:
        new = value
    data.setdefault(section, {})[key] = new
    return f"{name}: {section}.{key} = {new!r}", _toml(data), data


BEARING_GENERATORS: dict[str, Callable[[random.Random, bool, int],
                                       tuple[str, bytes, dict]]] = {
    "bearing-mutation": gen_bearing_mutation, "bearing-variant": gen_bearing_variant,
    "bearing-garbage": gen_bearing_garbage, "bearing-extreme": gen_bearing_extreme,
}


def generate(seed: int, quick: bool = False) -> list[Case]:
    """The cases of one fuzz run (deterministic for a seed)."""
    rng = random.Random(seed)
    cases: list[Case] = []
    for category, (n_full, n_quick) in COUNTS.items():
        for i in range(n_quick if quick else n_full):
            name = f"{category}-{i:03d}"
            if category == "garbage":
                desc, text = _garbage(rng, quick)
                cases.append(Case(name, category, desc, text))
                continue
            if category in BEARING_GENERATORS:
                desc, text, data = BEARING_GENERATORS[category](rng, quick, i)
                sol = data.get("solver", {})
                limit, budget = sol.get("time_limit"), sol.get("iteration_budget")
                cases.append(Case(name, category, desc, text,
                                  limit if isinstance(limit, float) and limit > 0 else None,
                                  budget if type(budget) is int else None, command="bearing"))
                continue
            desc, data = GENERATORS[category](rng, quick)
            data = _budget(rng, copy.deepcopy(data), quick)
            sol = data["solver"]
            limit = sol.get("time_limit")
            budget = sol.get("iteration_budget")
            cases.append(Case(name, category, desc, _toml(data),
                              limit if isinstance(limit, float) and limit > 0 else None,
                              budget))
    return cases


# ---------------------------------------------------------------------------------------
# running
# ---------------------------------------------------------------------------------------
def _child(argv: list[str], out_path: str, err_path: str) -> None:
    """Forked process: run the command line with stdout/stderr going to files."""
    out = open(out_path, "w", encoding="utf-8")
    err = open(err_path, "w", encoding="utf-8")
    os.dup2(out.fileno(), 1)
    os.dup2(err.fileno(), 2)
    sys.stdout, sys.stderr = out, err
    try:
        from bearing_fem import cli

        code = cli.main(argv)
    except BaseException:  # an escaped exception is what the fuzz looks for
        traceback.print_exc()
        code = 1
    out.flush()
    err.flush()
    os._exit(code)


def _argv(case: Case, path: str, outdir: str) -> list[str]:
    """The command line of one case."""
    if case.command == "bearing":
        return ["bearing", path, "--out", outdir, "--no-figures"]
    return ["solve", path, "--out", outdir]


def _start(case: Case, work: Path) -> tuple[Any, float]:
    folder = work / case.name
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / ("bearing.toml" if case.command == "bearing" else "scene.toml")
    path.write_bytes(case.text)
    proc = multiprocessing.get_context("fork").Process(
        target=_child, args=(_argv(case, str(path), str(folder / "out")),
                             str(folder / "stdout.txt"), str(folder / "stderr.txt")))
    proc.start()
    return proc, time.perf_counter()


def _strict_json(path: Path) -> tuple[dict | None, bool]:
    """(summary, finite): parse strictly; NaN/Infinity constants or non-finite floats
    make ``finite`` False."""
    finite = True

    def reject(token):
        nonlocal finite
        finite = False
        return float(token.replace("Infinity", "inf"))

    data = json.loads(path.read_text(encoding="utf-8"), parse_constant=reject)

    def walk(v):
        nonlocal finite
        if isinstance(v, float) and not math.isfinite(v):
            finite = False
        elif isinstance(v, dict):
            for x in v.values():
                walk(x)
        elif isinstance(v, list):
            for x in v:
                walk(x)
    walk(data)
    return data, finite


def check(case: Case, folder: Path, exit_code: int | None, wall: float) -> Outcome:
    """Apply every check of the module docstring to one finished run."""
    err = (folder / "stderr.txt").read_text(encoding="utf-8", errors="replace") \
        if (folder / "stderr.txt").exists() else ""
    res = Outcome(case, exit_code, wall, stderr=err)
    v = res.violations
    if exit_code is None:
        v.append("budget-time")  # killed at the hard timeout
        return res
    if exit_code not in (0, 2, 3) or "Traceback" in err:
        v.append("traceback")
    if RAW_WARNING.search(err):
        v.append("raw-warning")
    out = folder / "out"
    written = sorted(p.name for p in out.iterdir()) if out.is_dir() else []
    if exit_code == 2:
        if written:
            v.append("exit-vs-success")
        lines = [ln for ln in err.splitlines() if ln.strip()]
        if len(lines) != 1 or len(lines[0]) > MAX_MESSAGE:
            v.append("long-message")
        return res
    bearing = case.command == "bearing"
    summary_path = out / ("bearing_summary.json" if bearing else "summary.json")
    if not summary_path.is_file():
        if exit_code in (0, 3):
            v.append("exit-vs-success")
        return res
    summary, finite = _strict_json(summary_path)
    if not finite:
        v.append("nonfinite")
    res.status, res.success = summary.get("status", ""), summary.get("success")
    res.summary_wall_s = summary.get("wall_time_s")
    if (exit_code == 0) != (res.success is True) or (exit_code == 3) != (res.success is False):
        v.append("exit-vs-success")
    if bearing:
        _check_bearing(case, summary, res)
        return res
    # with mesh.target_error, every grid's solve counts against the one budget
    res.newton_iterations = (summary.get("refinement") or {}).get(
        "newton_iterations", summary.get("newton_iterations"))
    if res.success is True:
        h_min, h_c = summary.get("h_min"), summary.get("h_central")
        if any(isinstance(h, (int, float)) and h < 0 for h in (h_min, h_c)):
            v.append("negative-film")
        if isinstance(h_min, (int, float)) and isinstance(h_c, (int, float)) and h_min > h_c:
            v.append("film-order")
        load = summary.get("load")
        if isinstance(load, (int, float)) and load < 0:
            v.append("negative-load")
        f = summary.get("friction_coefficient")
        if isinstance(f, (int, float)) and abs(f) > 1.0:
            v.append("friction>1")
        heat = summary.get("heat_power")
        if isinstance(heat, (int, float)) and heat < 0:
            v.append("negative-heat")
    if case.iteration_budget is not None and isinstance(res.newton_iterations, int) \
            and res.newton_iterations > case.iteration_budget:
        v.append("budget-iterations")
    if case.time_limit is not None and isinstance(res.summary_wall_s, (int, float)):
        res.time_ratio = res.summary_wall_s / case.time_limit
        if res.summary_wall_s > TIME_FACTOR * case.time_limit + TIME_SLACK:
            v.append("budget-time")
    return res


#: Keys of a bearing summary whose numbers must not be negative in a successful run,
#: by the check they belong to (``heat_power_stabilisation``, a difference of two heat
#: forms, may have either sign and is not listed).
BEARING_SIGNED_KEYS = {
    "negative-film": ("h_min", "h_central", "h_central_formula"),
    "negative-load": ("load", "load_outer", "load_solved", "radial_load", "axial_load",
                      "max_element_load", "centrifugal_force"),
    "negative-torque": ("friction_torque", "friction_torque_inner", "friction_torque_outer",
                        "torque", "torque_viscous", "torque_load"),
    "negative-heat": ("heat_power", "heat_power_inner", "heat_power_outer",
                      "heat_power_poiseuille_direct", "friction_heat_power",
                      "churning_heat_power"),
}


def _walk_items(data: Any, skip: tuple[str, ...] = ("bearing", "units", "error_estimate")):
    """Every (key, value, parent mapping) of a nested summary, outside the ``skip`` keys
    (the echo of the input, the units, and the relative errors, which reuse the names
    of the quantities)."""
    if isinstance(data, dict):
        for key, value in data.items():
            if key in skip:
                continue
            yield key, value, data
            yield from _walk_items(value, skip)
    elif isinstance(data, list):
        for value in data:
            yield from _walk_items(value, skip)


def _check_bearing(case: Case, summary: dict, res: Outcome) -> None:
    """The checks of a bearing summary: signs and friction coefficients of a successful
    one (anywhere in it: totals, elements, contacts, film formulas, empirical models),
    h_min <= h_central of each contact, and each contact's Newton iterations and wall
    time (per slice for a profiled roller, whose contact sums its slices) against the
    per-contact budget (``[solver]`` applies to every contact scene), the bearing's wall
    time against the limit times its distinct contact solves."""
    v = res.violations
    contacts = [c for e in summary.get("elements") or [] for c in (e.get("inner"),
                                                                   e.get("outer"))
                if isinstance(c, dict)]
    # a profiled roller's contact sums its slices' iterations and wall times (each slice
    # one scene with the [solver] budget): compared per slice
    per = [max(1, c.get("slices") or 1) for c in contacts]
    its = [c["newton_iterations"] / n for c, n in zip(contacts, per)
           if isinstance(c.get("newton_iterations"), int)]
    res.newton_iterations = math.ceil(max(its)) if its else None
    if res.success is True:
        found: list[str] = []
        for key, value, parent in _walk_items(summary):
            if not isinstance(value, (int, float)) or isinstance(value, bool):
                continue
            for name, keys in BEARING_SIGNED_KEYS.items():
                if key in keys and value < 0:
                    found.append(name)
            if key == "friction_coefficient" and abs(value) > 1.0:
                found.append("friction>1")
            if key == "h_min" and isinstance(parent.get("h_central"), (int, float)) \
                    and value > parent["h_central"]:
                found.append("film-order")
        v.extend(dict.fromkeys(found))
    if case.iteration_budget is not None and res.newton_iterations is not None \
            and res.newton_iterations > case.iteration_budget:
        v.append("budget-iterations")
    if case.time_limit is None:
        return
    limit = case.time_limit
    walls = [c["wall_time_s"] / n for c, n in zip(contacts, per)
             if isinstance(c.get("wall_time_s"), (int, float))]
    counts = summary.get("contact_solves") or {}
    solves = (counts.get("distinct_solved") or 0) + (counts.get("solved_again") or 0)
    ratios = [w / limit for w in walls]
    if isinstance(res.summary_wall_s, (int, float)):
        ratios.append(res.summary_wall_s / (limit * max(1, solves)))
        if res.summary_wall_s > TIME_FACTOR * limit * max(1, solves) + TIME_SLACK:
            v.append("budget-time")
    res.time_ratio = max(ratios, default=None)
    if any(w > TIME_FACTOR * limit + TIME_SLACK for w in walls) and "budget-time" not in v:
        v.append("budget-time")


def run_cases(cases: list[Case], work: Path, workers: int = 2) -> list[Outcome]:
    """Run every case, ``workers`` at a time, each in a forked process."""
    import bearing_fem.cli  # noqa: F401  (imported once here, shared by every fork)
    import bearing_fem.contacts.dispatch  # noqa: F401
    import bearing_fem.io  # noqa: F401
    import bearing_fem.bearing  # noqa: F401

    pending = list(cases)
    running: list[tuple[Case, Any, float]] = []
    done: dict[str, Outcome] = {}
    while pending or running:
        while pending and len(running) < workers:
            case = pending.pop(0)
            proc, t0 = _start(case, work)
            running.append((case, proc, t0))
        time.sleep(0.01)
        for item in list(running):
            case, proc, t0 = item
            limit = (HARD_TIMEOUT_BEARING if case.command == "bearing"
                     else (case.time_limit or 0.0) * 3.0 + HARD_TIMEOUT)
            elapsed = time.perf_counter() - t0
            if proc.is_alive() and elapsed < limit:
                continue
            if proc.is_alive():
                proc.kill()
                proc.join()
                code = None
            else:
                proc.join()
                code = proc.exitcode
            running.remove(item)
            done[case.name] = check(case, work / case.name, code, elapsed)
    return [done[c.name] for c in cases]


# ---------------------------------------------------------------------------------------
def _write_tables(outcomes: list[Outcome], outdir: Path) -> None:
    cols = ["case", "category", "description", "exit", "status", "success", "wall_s",
            "solve_wall_s", "time_limit_s", "newton_iterations", "iteration_budget",
            "violations"]
    rows = [[o.case.name, o.case.category, o.case.description, o.exit_code, o.status,
             o.success, f"{o.wall_s:.2f}",
             None if o.summary_wall_s is None else f"{o.summary_wall_s:.2f}",
             o.case.time_limit, o.newton_iterations, o.case.iteration_budget,
             " ".join(o.violations)] for o in outcomes]
    with open(outdir / "cases.csv", "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(cols)
        w.writerows(rows)
    lines = ["| " + " | ".join(cols) + " |", "|" + "---|" * len(cols)]
    for r in rows:
        lines.append("| " + " | ".join("" if x is None else str(x).replace("|", "/")
                                       for x in r) + " |")
    (outdir / "cases.md").write_text("\n".join(lines) + "\n", encoding="utf-8")


def main(outdir: str | Path = "out/scene_fuzz", quick: bool = False, seed: int = 20240612,
         workers: int = 2, categories: list[str] | None = None) -> dict:
    """Generate, run and check the cases; write the tables; return the counts.

    Returns
    -------
    dict
        ``cases``, ``seed``, ``max_time_ratio`` (largest solve wall time over its time
        limit; a bearing: the largest of its contact scenes' ratios and of its wall time
        over the limit times its distinct solves), ``max_iteration_ratio`` (largest
        Newton iterations over the budget; a bearing: its contact scene with the most),
        ``by_category``, ``by_exit`` (exit code -> count),
        ``by_status``, ``violations`` (number of cases with one), ``by_violation``
        (check -> count), ``violating`` (list of ``{"case", "description",
        "violations", "status", "exit", "reproducer"}``), ``wall_s`` (whole study).
    """
    t0 = time.perf_counter()
    outdir = Path(outdir)
    outdir.mkdir(parents=True, exist_ok=True)
    work = outdir / "runs"
    shutil.rmtree(work, ignore_errors=True)
    repro = outdir / "violations"
    shutil.rmtree(repro, ignore_errors=True)
    cases = generate(seed, quick)
    if categories:  # a subset of the same cases (generation does not depend on it)
        unknown = sorted(set(categories) - set(COUNTS))
        if unknown:
            raise ValueError(f"unknown categories {unknown}; known: {', '.join(COUNTS)}")
        cases = [c for c in cases if c.category in categories]
    outcomes = run_cases(cases, work, workers)
    _write_tables(outcomes, outdir)
    violating = []
    for o in outcomes:
        if not o.violations:
            continue
        repro.mkdir(exist_ok=True)
        path = repro / f"{o.case.name}.toml"
        path.write_bytes(o.case.text)
        violating.append({"case": o.case.name, "description": o.case.description,
                          "violations": o.violations, "status": o.status,
                          "exit": o.exit_code, "reproducer": str(path),
                          "stderr": o.stderr[-400:]})
    count = lambda key: {k: sum(1 for o in outcomes if key(o) == k)  # noqa: E731
                         for k in sorted({str(key(o)) for o in outcomes})}
    by_violation: dict[str, int] = {}
    for o in outcomes:
        for name in o.violations:
            by_violation[name] = by_violation.get(name, 0) + 1
    time_ratios = [o.time_ratio for o in outcomes if o.time_ratio is not None]
    its_ratios = [o.newton_iterations / o.case.iteration_budget for o in outcomes
                  if o.case.iteration_budget and isinstance(o.newton_iterations, int)]
    result = {
        "cases": len(outcomes), "seed": seed, "quick": quick,
        "max_time_ratio": max(time_ratios, default=None),
        "max_iteration_ratio": max(its_ratios, default=None),
        "by_category": count(lambda o: o.case.category),
        "by_exit": count(lambda o: str(o.exit_code)),
        "by_status": count(lambda o: o.status or "-"),
        "violations": len(violating), "by_violation": by_violation, "violating": violating,
        "wall_s": time.perf_counter() - t0,
    }
    (outdir / "summary.json").write_text(json.dumps(result, indent=2), encoding="utf-8")
    shutil.rmtree(work, ignore_errors=True)
    return result


if __name__ == "__main__":
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("outdir", nargs="?", default="out/scene_fuzz")
    parser.add_argument("--quick", action="store_true", help="the ~40-case subset")
    parser.add_argument("--seed", type=int, default=20240612)
    parser.add_argument("--only", nargs="+", metavar="CATEGORY",
                        help=f"run only these categories ({', '.join(COUNTS)})")
    args = parser.parse_args()
    res = main(args.outdir, quick=args.quick, seed=args.seed, categories=args.only)
    print(json.dumps({k: v for k, v in res.items() if k != "violating"}, indent=2))
    for item in res["violating"]:
        print(f"{item['case']}: {' '.join(item['violations'])} ({item['description']}; "
              f"status {item['status']}, exit {item['exit']}) -> {item['reproducer']}")
