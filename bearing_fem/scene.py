"""Scenes: frozen, keyword-only, SI dataclasses, validated when built.

A scene is everything a solve needs: contact geometry, materials, lubricant,
kinematics, load (or prescribed gap), model options, mesh and solver settings.
Build one from a TOML file (:meth:`Scene.from_toml`), from a dict
(:meth:`Scene.from_dict`) or directly from the dataclasses; change one by copy
(``dataclasses.replace``). Every invalid value raises :class:`~bearing_fem.errors.SceneError`
naming the field, the value and the unit. The keys are documented in ``docs/scenes.md``.
"""
from __future__ import annotations

import math
import unicodedata
from dataclasses import MISSING, dataclass, field, fields, replace
from pathlib import Path
from typing import Any, Literal, Mapping, Sequence

import numpy as np

from .errors import SceneError
from .physics.rheology import viscosity_function
from .physics.traction import GENERIC_MINERAL_OIL, TRACTION_MODELS
from .validation import (require_finite, require_int, require_nonnegative, require_positive,
                         shown)

try:  # Python >= 3.11
    import tomllib
except ModuleNotFoundError:  # pragma: no cover
    import tomli as tomllib  # type: ignore[no-redef]


# ---------------------------------------------------------------------------------------
# validation helpers
# ---------------------------------------------------------------------------------------
def show_value(value: Any) -> str:
    """A bad value for an error message, cut short (:func:`bearing_fem.validation.shown`),
    also for integers beyond Python's int -> str digit limit and deeply nested lists.

    Parameters
    ----------
    value : Any
        The offending value (any type: a scene file can hold anything).

    Returns
    -------
    str
    """
    try:
        return shown(value)
    except ValueError:  # an integer beyond Python's int -> str digit limit
        digits = int(value.bit_length() * math.log10(2)) + 1
        return f"<an integer of about {digits} digits>"
    except RecursionError:
        return f"<a deeply nested {type(value).__name__}>"


def field_name_prefix(obj: Any) -> str:
    """Section name of a scene/bearing section dataclass (its ``_section``), for messages."""
    return getattr(obj, "_section", type(obj).__name__.lower())


def plain_number(value: Any) -> Any:
    """A numpy integer or floating scalar as the Python int or float it holds (a value
    from ``np.linspace`` or ``np.arange`` is a number like any other); anything else,
    numpy booleans included, unchanged.

    Parameters
    ----------
    value : Any

    Returns
    -------
    Any
    """
    if isinstance(value, (np.integer, np.floating)):
        return value.item()
    return value


def _plain_tree(data: Any) -> Any:
    """``data`` with every numpy number in its mappings and lists made plain
    (:func:`plain_number`)."""
    if isinstance(data, Mapping):
        return {k: _plain_tree(v) for k, v in data.items()}
    if isinstance(data, (list, tuple)):
        return type(data)(_plain_tree(v) for v in data)
    return plain_number(data)


def _scalar(obj: Any, name: str, unit: str) -> tuple[str, Any]:
    """The field's full name and value, or SceneError unless the value is one real number
    (not a bool, a string, a list, ...; a numpy number counts as its Python value)."""
    value = plain_number(getattr(obj, name))
    full = f"{field_name_prefix(obj)}.{name}"
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise SceneError(f"{full} must be a number in {unit}, got {show_value(value)} "
                         f"({type(value).__name__})")
    if isinstance(value, int) and value.bit_length() > 1024:  # beyond the double range
        raise SceneError(f"{full} must be finite ({unit}), got {show_value(value)} (beyond "
                         "the floating-point range)")
    return full, value


def field_number(obj: Any, name: str, unit: str) -> float:
    """Field ``name`` of a section dataclass as a finite float (stored back), else
    SceneError naming the field, the value and ``unit``."""
    full, value = _scalar(obj, name, unit)
    value = require_finite(full, value, unit, error=SceneError)
    object.__setattr__(obj, name, value)
    return value


def field_poisson(obj: Any, name: str) -> float:
    """Field ``name`` as a Poisson ratio in (-1, 0.5] [-] (stored back as a float), else
    SceneError naming the field and the value."""
    value = field_number(obj, name, "(dimensionless)")
    if not -1.0 < value <= 0.5:
        raise SceneError(f"{field_name_prefix(obj)}.{name} must lie in (-1, 0.5] "
                         f"(dimensionless), got {value!r}")
    return value


def field_positive(obj: Any, name: str, unit: str) -> float:
    """Field ``name`` as a finite float > 0 (stored back), else SceneError (with ``unit``)."""
    full, value = _scalar(obj, name, unit)
    value = require_positive(full, value, unit, error=SceneError)
    object.__setattr__(obj, name, value)
    return value


def field_nonnegative(obj: Any, name: str, unit: str) -> float:
    """Field ``name`` as a finite float >= 0 (stored back), else SceneError (with ``unit``)."""
    full, value = _scalar(obj, name, unit)
    value = require_nonnegative(full, value, unit, error=SceneError)
    object.__setattr__(obj, name, value)
    return value


def field_target_error(obj: Any) -> float:
    """``obj.target_error`` (a ``[mesh]`` section's) in :data:`TARGET_ERROR_RANGE` [-], else
    SceneError naming it."""
    return field_bounded(obj, "target_error", "(dimensionless; 0.05 is 5 %)",
                         *TARGET_ERROR_RANGE,
                         why="a relative error; below 1e-3 the estimate is at its noise, "
                             "above 0.5 it is no error bar")


def field_bounded(obj: Any, name: str, unit: str, lo: float, hi: float, *,
             open_low: bool = False, why: str = "") -> float:
    """A finite number in [lo, hi] (or (lo, hi] with ``open_low``), else SceneError.

    The bounds are those documented in ``docs/scenes.md`` ("Ranges"); ``why`` is a short
    reason appended to the message.
    """
    value = field_number(obj, name, unit)
    low_ok = value > lo if open_low else value >= lo
    if not (low_ok and value <= hi):
        bracket = "(" if open_low else "["
        raise SceneError(f"{field_name_prefix(obj)}.{name} must lie in {bracket}{lo:g}, {hi:g}] "
                         f"{unit}, got {value!r}" + (f" ({why})" if why else ""))
    return value


def field_integer(obj: Any, name: str, lo: int, hi: int, what: str) -> int:
    """Field ``name`` as an integer in [lo, hi] (``what`` says what it counts), else SceneError."""
    value = require_int(f"{field_name_prefix(obj)}.{name}", getattr(obj, name), lo, hi, what=what,
                        error=SceneError)
    object.__setattr__(obj, name, value)
    return value


def field_choice(obj: Any, name: str, allowed: tuple[str, ...]) -> str:
    """Field ``name`` as one of the strings ``allowed``, else SceneError."""
    value = getattr(obj, name)
    if not isinstance(value, str) or value not in allowed:
        raise SceneError(f"{field_name_prefix(obj)}.{name} must be one of "
                         f"{', '.join(map(repr, allowed))}, got {show_value(value)}")
    return value


def field_bool(obj: Any, name: str) -> bool:
    """Field ``name`` as a bool (TOML true/false), else SceneError."""
    value = getattr(obj, name)
    if not isinstance(value, bool):
        raise SceneError(f"{field_name_prefix(obj)}.{name} must be true or false, got "
                         f"{show_value(value)}")
    return value


def field_range(obj: Any, name: str, *, hertz_zone: bool = False
                ) -> tuple[float, float] | None:
    """Field ``name`` as a domain (start, end) in Hertz half-widths (or sqrt(2 r h0) for
    rigid scenes) with start < 0 < end and both ends within :data:`MAX_RANGE`; None stays
    None; SceneError otherwise. With ``hertz_zone`` (ranges known to be in Hertz
    half-widths) it must also contain the Hertz zone (:func:`require_hertz_zone`)."""
    r = getattr(obj, name)
    if r is None:
        return None
    if isinstance(r, (list, tuple)):
        r = [plain_number(v) for v in r]
    where = f"{field_name_prefix(obj)}.{name}"
    if (not isinstance(r, (list, tuple)) or len(r) != 2
            or any(isinstance(v, bool) or not isinstance(v, (int, float)) for v in r)):
        raise SceneError(f"{where} must be two numbers [start, end] (in Hertz half-widths), "
                         f"got {show_value(r)}")
    try:
        lo, hi = float(r[0]), float(r[1])
    except OverflowError:
        lo = hi = math.inf
    if not (math.isfinite(lo) and math.isfinite(hi)) or lo >= 0.0 or hi <= 0.0:
        raise SceneError(f"{where} must satisfy start < 0 < end (in Hertz half-widths), "
                         f"got {show_value(r)}")
    if max(-lo, hi) > MAX_RANGE:
        raise SceneError(f"{where} must lie within [-{MAX_RANGE:g}, {MAX_RANGE:g}] (in Hertz "
                         f"half-widths, or sqrt(2 r h0) for rigid scenes), got {show_value(r)}")
    object.__setattr__(obj, name, (lo, hi))
    if hertz_zone:
        require_hertz_zone(where, (lo, hi))
    return lo, hi


def require_hertz_zone(where: str, r: tuple[float, float]) -> None:
    """Check that a domain contains the Hertz zone: start <= -:data:`HERTZ_ZONE` and end
    >= :data:`HERTZ_ZONE`. The one rule for elastic scenes with a load and for bearings.

    Parameters
    ----------
    where : str
        The field's name for the message (e.g. ``"mesh.x_range"``).
    r : (float, float)
        The domain (start, end) in Hertz half-widths [-] (b, or the semi-axes a_x, a_y).

    Raises
    ------
    SceneError
        The range does not contain [-1, 1]; the message names the field, its value and
        the unit (a range given in metres, mostly).
    """
    lo, hi = r
    if lo > -HERTZ_ZONE or hi < HERTZ_ZONE:
        raise SceneError(f"{where} = [{lo:g}, {hi:g}] (in Hertz half-widths) does not contain "
                         f"the Hertz zone [-{HERTZ_ZONE:g}, {HERTZ_ZONE:g}]: the range is in "
                         "units of the Hertz half-width, not in metres (e.g. "
                         f"{'[-3, 3]' if where.endswith('y_range') else '[-4.5, 1.5]'})")


def field_piezo(obj: Any, name: str = "piezo") -> float:
    """Field ``name`` as a pressure-viscosity coefficient alpha in [0, 1e-6] 1/Pa (typical
    oils 1e-8..3e-8), else SceneError."""
    value = field_nonnegative(obj, name, "1/Pa")
    if value > 1e-6:
        raise SceneError(f"{field_name_prefix(obj)}.{name} must be <= 1e-6 1/Pa (typical oils "
                         f"1e-8..3e-8), got {value!r}")
    return value


def field_piezo_table(obj: Any) -> None:
    """The optional alpha(t) table of a section: ``piezo_temperatures`` [deg C] (strictly
    ascending, in (-273.15, :data:`TEMPERATURE_RANGE` max]) and ``piezo_values`` [1/Pa]
    (each in (0, 1e-6]), both or neither, of equal length; stored back as tuples of
    floats, SceneError otherwise."""
    where = field_name_prefix(obj)
    ts, vs = obj.piezo_temperatures, obj.piezo_values
    if (ts is None) != (vs is None):
        raise SceneError(f"{where}: give both {where}.piezo_temperatures (deg C) and "
                         f"{where}.piezo_values (1/Pa), or neither; got {show_value(ts)}, "
                         f"{show_value(vs)}")
    if ts is None:
        return
    table = _float_list(ts), _float_list(vs)
    if table[0] is None or table[1] is None or not len(ts) == len(vs) >= 1:
        raise SceneError(f"{where}.piezo_temperatures (deg C) and {where}.piezo_values "
                         f"(1/Pa) must be equal-length lists of finite numbers, got "
                         f"{show_value(ts)}, {show_value(vs)}")
    ts, vs = table
    if any(b <= a for a, b in zip(ts, ts[1:])):
        raise SceneError(f"{where}.piezo_temperatures must be strictly ascending (deg C), "
                         f"got {show_value(ts)}")
    t_hi = TEMPERATURE_RANGE[1]
    if any(not -273.15 < t <= t_hi for t in ts):
        raise SceneError(f"{where}.piezo_temperatures must lie in (-273.15, {t_hi:g}] "
                         f"deg C, got {show_value(ts)}")
    if any(not 0.0 < v <= 1e-6 for v in vs):
        raise SceneError(f"{where}.piezo_values must lie in (0, 1e-6] 1/Pa, got "
                         f"{show_value(vs)}")
    object.__setattr__(obj, "piezo_temperatures", ts)
    object.__setattr__(obj, "piezo_values", vs)


def section_from_table(table: str, klass: type, section: Any) -> Any:
    """Build the section dataclass ``klass`` from the TOML table ``[table]``.

    Raises SceneError when the table is not a mapping, names a key ``klass`` does not
    have (the message lists the known keys) or lacks a key without a default.
    """
    if not isinstance(section, Mapping):
        raise SceneError(f"[{table}] must be a table, got {show_value(section)}")
    names = [f.name for f in fields(klass) if not f.name.startswith("_")]
    bad = [k for k in section if k not in names]
    if bad:
        raise SceneError(f"unknown key(s) {_names(bad, prefix=table + '.')}; "
                         f"known keys of [{table}]: {', '.join(names)}")
    required = [f.name for f in fields(klass) if not f.name.startswith("_")
                and f.default is MISSING and f.default_factory is MISSING]
    missing = [k for k in required if k not in section]
    if missing:
        raise SceneError(f"missing key(s) {', '.join(f'{table}.{k}' for k in missing)}")
    return klass(**dict(section))


def section_to_table(section: Any) -> dict[str, Any]:
    """The TOML table of a section dataclass: its public fields, None entries omitted,
    tuples as lists (the inverse of :func:`section_from_table`)."""
    table = {}
    for f in fields(section):
        if f.name.startswith("_"):
            continue
        v = getattr(section, f.name)
        if v is not None:
            table[f.name] = list(v) if isinstance(v, tuple) else v
    return table


def sections_from_dict(data: Any, sections: Mapping[str, tuple[str, type]],
                       required: Sequence[str], what: str, hint: str = "") -> dict[str, Any]:
    """Keyword arguments of a file's dataclass (a scene, a bearing) from a nested mapping
    with the TOML layout: an optional ``title`` and one table per section.

    Parameters
    ----------
    data : mapping
        The parsed file.
    sections : mapping
        TOML table name -> (attribute name, section dataclass), in file order.
    required : sequence of str
        The tables a file must have.
    what : str
        What the file holds, in messages (``"scene"``, ``"bearing"``).
    hint : str
        Appended to the message naming unknown tables.

    Returns
    -------
    dict
        ``title`` (when given) and attribute name -> section (:func:`section_from_table`)
        for each table present. SceneError when ``data`` is not a mapping, names an
        unknown table or lacks a required one.
    """
    if not isinstance(data, Mapping):
        raise SceneError(f"a {what} must be a table of sections, got {type(data).__name__}")
    known = ("title",) + tuple(sections)
    unknown = [k for k in data if k not in known]
    if unknown:
        raise SceneError(f"unknown {what} section(s) {_names(unknown)}; "
                         f"known: {', '.join(known)}{hint}")
    absent = [name for name in required if name not in data]
    if absent:
        raise SceneError(f"missing {what} section{'s' if len(absent) > 1 else ''} "
                         + ", ".join(f"[{name}]" for name in absent))
    kwargs: dict[str, Any] = {}
    if "title" in data:
        kwargs["title"] = data["title"]
    for table, (attr, klass) in sections.items():
        if table in data:
            kwargs[attr] = section_from_table(table, klass, data[table])
    return kwargs


def sections_to_dict(obj: Any, sections: Mapping[str, tuple[str, type]]) -> dict[str, Any]:
    """Nested dict with the TOML layout of a file's dataclass (the inverse of
    :func:`sections_from_dict`): ``title`` when not empty, then one table per section
    that is not None (:func:`section_to_table`)."""
    out: dict[str, Any] = {}
    if obj.title:
        out["title"] = obj.title
    for table, (attr, _) in sections.items():
        section = getattr(obj, attr)
        if section is not None:
            out[table] = section_to_table(section)
    return out


def parse_toml(text: str, source: str, what: str = "a scene") -> dict[str, Any]:
    """Parse TOML text (a leading UTF-8 byte-order mark is dropped); SceneError naming
    ``source`` when it is not valid TOML or nested too deeply to read (``what`` the file
    should have been, e.g. ``"a scene"``)."""
    if text.startswith("\ufeff"):  # a UTF-8 byte-order mark (some editors write one)
        text = text[1:]
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise SceneError(f"{source} is not valid TOML: {exc}") from None
    except RecursionError:
        raise SceneError(f"{source} is not {what}: its arrays or tables are nested "
                         "too deeply to read") from None


def read_text_file(path: str | Path, what: str) -> str:
    """The text of a UTF-8 file; SceneError naming ``what`` (e.g. ``"scene file"``) and
    the path when the file cannot be read or is not UTF-8 text."""
    try:
        return Path(path).read_text(encoding="utf-8")
    except OSError as exc:
        raise SceneError(f"cannot read {what} {str(path)!r}: {exc.strerror or exc}") from None
    except UnicodeDecodeError as exc:
        raise SceneError(f"{what} {str(path)!r} is not UTF-8 text ({exc.reason})") from None


def read_toml(path: str | Path, what: str) -> dict[str, Any]:
    """Read a TOML file (:func:`read_text_file`, :func:`parse_toml`); SceneError naming
    ``what`` (e.g. ``"sweep file"``) and the path when it is unreadable or invalid."""
    return parse_toml(read_text_file(path, what), f"{what} {str(path)!r}", "readable TOML")


def _float_list(values: Any) -> tuple[float, ...] | None:
    """A list of finite numbers as floats, or None if it is not one."""
    if not isinstance(values, (list, tuple)):
        return None
    out = []
    for v in values:
        if isinstance(v, bool) or not isinstance(v, (int, float)):
            return None
        try:
            v = float(v)
        except OverflowError:
            return None
        if not math.isfinite(v):
            return None
        out.append(v)
    return tuple(out)


def _names(keys: list[Any], prefix: str = "", most: int = 5) -> str:
    """Unknown key names for a message: each cut short, at most ``most`` of them."""
    shown = []
    for k in keys[:most]:
        text = f"{prefix}{k}" if isinstance(k, str) else f"{prefix}{show_value(k)}"
        shown.append(text if len(text) <= 40 else f"{text[:30]}... ({len(text)} characters)")
    more = f" and {len(keys) - most} more" if len(keys) > most else ""
    return ", ".join(shown) + more


def _check_title(title: Any) -> None:
    """A title is one line of printable text (it is stored in HDF5 attributes and shown
    in figures): no control characters, at most :data:`MAX_TITLE` characters."""
    if not isinstance(title, str):
        raise SceneError(f"title must be a string, got {show_value(title)}")
    if len(title) > MAX_TITLE:
        raise SceneError(f"title must have at most {MAX_TITLE} characters, got "
                         f"{len(title)}: {show_value(title)}")
    bad = [ch for ch in title if unicodedata.category(ch) in ("Cc", "Cs")]
    if bad:
        raise SceneError(f"title must be one line of printable text, got the control "
                         f"character {bad[0]!r} (U+{ord(bad[0]):04X}) in {show_value(title)}")


# ---------------------------------------------------------------------------------------
# ranges (docs/scenes.md, "Ranges": each bound with its reason)
# ---------------------------------------------------------------------------------------
#: Radii and lengths [m]: from a micro-contact (1 um) to the largest slewing bearings.
LENGTH_RANGE = (1e-6, 10.0)
#: Largest ratio of the reduced radii ry/rx or rx/ry of a point contact [-] (a toroidal
#: roller is about 100; beyond 1e4 treat the contact as a line contact).
MAX_RADIUS_RATIO = 1e4
#: Young's moduli and E' [Pa]: from soft elastomers (1 MPa) up; E = 208 Pa (GPa meant) is
#: rejected. The upper end lies far beyond diamond (1.2e12 Pa) so that a nearly rigid
#: elastic body can approach the rigid limit; it keeps every Hertz and Moes scale finite.
MODULUS_RANGE = (1e6, 1e30)
#: Viscosity at ambient pressure [Pa s]: from gases (air 1.8e-5) to bitumen.
VISCOSITY_RANGE = (1e-6, 1e6)
#: Viscosity range of the Roelands law [Pa s]: ln eta0 + 9.67 >= 0.5 keeps its pressure
#: index Z = alpha p0 / (ln eta0 + 9.67) finite.
ROELANDS_VISCOSITY = (math.exp(0.5 - 9.67), 1e4)
#: Largest surface speed |u| [m/s] (the fastest bearings run at about 100 m/s).
MAX_SPEED = 1e3
#: Smallest mean (entrainment) speed [m/s]: below it, entrainment does not build a film.
MIN_MEAN_SPEED = 1e-6
#: Load [N for a point contact, N/m for a line contact].
FORCE_RANGE = (1e-6, 1e12)
#: Prescribed rigid offset [m]: from below atomic size to a millimetre film.
GAP_RANGE = (1e-10, 1e-3)
#: Largest Hertz semi-axis over its reduced radius (b/rx, a_x/rx, a_y/ry) [-]: Hertz
#: theory and the half-space model need a contact small against the radii.
MAX_HERTZ_RATIO = 0.5
#: Largest viscosity ratio eta(p_h)/eta0 at the Hertz pressure [-]: exp(700); beyond
#: exp(709) the viscosity overflows double precision (Barus: alpha p_h <= 700). Not applied
#: to Barus scenes with half-space elasticity: their film equation is solved in the
#: reduced pressure q = (1 - exp(-alpha p))/alpha, where exp(-alpha p) underflows to 0
#: (the film is frozen there) instead of exp(alpha p) overflowing; the viscosity itself is
#: then only reported (clipped, with a warning). Measured: the line map points
#: alpha p_h = 712, 855, 997 (Moes M = 1e4, L = 17.9 .. 25) converge in 14-17 Newton
#: iterations (``studies/stability_atlas.py``).
MAX_VISCOSITY_RATIO = math.exp(700.0)
#: Node spacings of ``mesh.grading``.
GRADINGS = ("uniform", "outlet")
#: Accepted ``mesh.target_error`` (of a contact scene and of a bearing) [-]: below 1e-3
#: the estimate is at its noise, above 0.5 it is no error bar.
TARGET_ERROR_RANGE = (1e-3, 0.5)
#: Largest |start|, |end| of mesh.x_range and mesh.y_range [Hertz half-widths or
#: sqrt(2 r h0)].
MAX_RANGE = 1e3
#: Half-width of the Hertz zone in its own units [-]: the mesh ranges of an elastic scene
#: with a load (and of a bearing's contacts) must contain [-1, 1], or the domain cuts off
#: the contact (:func:`require_hertz_zone`).
HERTZ_ZONE = 1.0
#: Temperatures [deg C] of the Prokofiev law (t > 0) up to where any oil decomposes.
TEMPERATURE_RANGE = (0.0, 500.0)
#: Longest title [characters].
MAX_TITLE = 200


# ---------------------------------------------------------------------------------------
# sections
# ---------------------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class Contact:
    """Contact geometry.

    Parameters
    ----------
    kind : {"line", "point"}
        Line contact (roller, per metre of length) or point/elliptical contact (ball).
    rx : float
        Reduced radius in the rolling direction x [m] (1/rx = 1/r1x + 1/r2x), in
        :data:`LENGTH_RANGE`.
    ry : float or None
        Reduced radius across the rolling direction [m]; point contacts only, in
        :data:`LENGTH_RANGE`, with ry/rx within 1/:data:`MAX_RADIUS_RATIO` ..
        :data:`MAX_RADIUS_RATIO` (a more slender contact is a line contact).
    length : float or None
        Effective contact length [m]; line contacts only, the summary gives the
        load, friction force and heat power over it (``*_total``).
    """

    _section = "contact"
    kind: Literal["line", "point"] = "line"
    rx: float
    ry: float | None = None
    length: float | None = None

    def __post_init__(self) -> None:
        field_choice(self, "kind", ("line", "point"))
        field_bounded(self, "rx", "m", *LENGTH_RANGE)
        if self.kind == "point":
            if self.ry is None:
                raise SceneError("contact.ry is required for a point contact (m)")
            field_bounded(self, "ry", "m", *LENGTH_RANGE)
            ratio = max(self.ry / self.rx, self.rx / self.ry)
            if ratio > MAX_RADIUS_RATIO:
                raise SceneError(f"contact.ry / contact.rx = {self.ry / self.rx:.4g} is too "
                                 f"slender for a point contact (the ratio of the radii must "
                                 f"lie within 1/{MAX_RADIUS_RATIO:g} .. {MAX_RADIUS_RATIO:g}; "
                                 f"rx = {self.rx!r} m, ry = {self.ry!r} m): treat it as a "
                                 "line contact")
            if self.length is not None:
                raise SceneError(f"contact.length applies to line contacts only, got "
                                 f"{show_value(self.length)} m for a point contact")
        else:
            if self.ry is not None:
                raise SceneError(f"contact.ry applies to point contacts only, got "
                                 f"{show_value(self.ry)} m for a line contact")
            if self.length is not None:
                field_bounded(self, "length", "m", *LENGTH_RANGE)


@dataclass(frozen=True, kw_only=True)
class Materials:
    """Elastic bodies: both Young's moduli and Poisson ratios, or E' directly.

    Parameters
    ----------
    e1, e2 : float
        Young's moduli [Pa], in :data:`MODULUS_RANGE` (so is E').
    nu1, nu2 : float
        Poisson ratios [-], in (-1, 0.5].
    reduced_modulus : float or None
        E' = 2 / ((1 - nu1^2)/E1 + (1 - nu2^2)/E2) [Pa]; give this *instead of* the four above.
    """

    _section = "materials"
    e1: float | None = None
    nu1: float | None = None
    e2: float | None = None
    nu2: float | None = None
    reduced_modulus: float | None = None

    def __post_init__(self) -> None:
        pair = [self.e1, self.nu1, self.e2, self.nu2]
        if self.reduced_modulus is not None:
            if any(v is not None for v in pair):
                raise SceneError("materials: give either reduced_modulus (Pa) or e1, nu1, e2, "
                                 "nu2, not both")
            field_bounded(self, "reduced_modulus", "Pa", *MODULUS_RANGE)
            return
        for name in ("e1", "nu1", "e2", "nu2"):
            if getattr(self, name) is None:
                raise SceneError(f"materials.{name} is required (or give materials."
                                 "reduced_modulus in Pa)")
        for name in ("e1", "e2"):
            field_bounded(self, name, "Pa", *MODULUS_RANGE)
        for name in ("nu1", "nu2"):
            field_poisson(self, name)
        e_prime = self.e_prime
        if not MODULUS_RANGE[0] <= e_prime <= MODULUS_RANGE[1]:
            raise SceneError(f"materials: the reduced modulus E' = {e_prime:.4g} Pa of e1, nu1, "
                             f"e2, nu2 must lie in [{MODULUS_RANGE[0]:g}, {MODULUS_RANGE[1]:g}] "
                             "Pa (a Poisson ratio near -1 makes it grow without bound)")

    @property
    def e_prime(self) -> float:
        """Reduced modulus E' [Pa] (Hamrock convention, docs/theory.md)."""
        if self.reduced_modulus is not None:
            return float(self.reduced_modulus)
        return 2.0 / ((1 - self.nu1**2) / self.e1 + (1 - self.nu2**2) / self.e2)


@dataclass(frozen=True, kw_only=True)
class Lubricant:
    """Newtonian lubricant.

    Parameters
    ----------
    viscosity : float
        eta0, viscosity at ambient pressure [Pa s], in :data:`VISCOSITY_RANGE`
        (:data:`ROELANDS_VISCOSITY` with the Roelands law). No default.
    piezo : float
        Barus pressure-viscosity coefficient alpha [1/Pa] (Roelands uses it for its slope).
    viscosity_law : {"barus", "roelands", "constant"}
    density : {"incompressible", "dowson-higginson"}
    """

    _section = "lubricant"
    viscosity: float
    piezo: float = 0.0
    viscosity_law: Literal["barus", "roelands", "constant"] = "barus"
    density: Literal["incompressible", "dowson-higginson"] = "incompressible"

    def __post_init__(self) -> None:
        field_bounded(self, "viscosity", "Pa s", *VISCOSITY_RANGE)
        field_piezo(self)
        field_choice(self, "viscosity_law", ("barus", "roelands", "constant"))
        field_choice(self, "density", ("incompressible", "dowson-higginson"))
        if self.viscosity_law == "roelands" and not ROELANDS_VISCOSITY[0] <= self.viscosity \
                <= ROELANDS_VISCOSITY[1]:
            raise SceneError(f"lubricant.viscosity = {self.viscosity!r} Pa s is outside the "
                             f"Roelands law's range [{ROELANDS_VISCOSITY[0]:.3g}, "
                             f"{ROELANDS_VISCOSITY[1]:g}] Pa s (ln eta0 + 9.67 must stay "
                             "positive and sane: at 6.3e-5 Pa s its pressure index is infinite)")

    @property
    def effective_piezo(self) -> float:
        """alpha actually used by the law [1/Pa] (0 for ``constant``)."""
        return 0.0 if self.viscosity_law == "constant" else float(self.piezo)


@dataclass(frozen=True, kw_only=True)
class Kinematics:
    """Surface speeds along +x [m/s], each within +-:data:`MAX_SPEED`. The mean
    (entrainment) speed must be at least :data:`MIN_MEAN_SPEED`."""

    _section = "kinematics"
    u1: float
    u2: float

    def __post_init__(self) -> None:
        field_bounded(self, "u1", "m/s", -MAX_SPEED, MAX_SPEED)
        field_bounded(self, "u2", "m/s", -MAX_SPEED, MAX_SPEED)
        if self.mean_speed <= 0.0:
            raise SceneError(f"kinematics: the mean speed (u1 + u2)/2 must be at least "
                             f"{MIN_MEAN_SPEED:g} m/s (positive: the inlet is at x < 0), got "
                             f"u1={self.u1!r}, u2={self.u2!r} m/s")
        if self.mean_speed < MIN_MEAN_SPEED:
            raise SceneError(f"kinematics: the mean speed (u1 + u2)/2 = {self.mean_speed!r} m/s "
                             f"is below {MIN_MEAN_SPEED:g} m/s, too slow to entrain a film "
                             f"(u1={self.u1!r}, u2={self.u2!r})")

    @property
    def mean_speed(self) -> float:
        """u_m = (u1 + u2)/2 [m/s]."""
        return 0.5 * (self.u1 + self.u2)

    @property
    def sliding_speed(self) -> float:
        """u_s = u1 - u2 [m/s]."""
        return self.u1 - self.u2

    @property
    def slide_to_roll(self) -> float:
        """SRR = u_s / u_m [-]."""
        return self.sliding_speed / self.mean_speed


@dataclass(frozen=True, kw_only=True)
class Load:
    """Either the load (``force``) or the rigid offset (``gap``), not both.

    Parameters
    ----------
    force : float or None
        N for a point contact, N per metre of length for a line contact, in
        :data:`FORCE_RANGE`.
    gap : float or None
        Prescribed rigid offset h0 [m] (no load balance), in :data:`GAP_RANGE`.
    """

    _section = "load"
    force: float | None = None
    gap: float | None = None

    def __post_init__(self) -> None:
        if (self.force is None) == (self.gap is None):
            raise SceneError("load: give exactly one of load.force (N or N/m) and load.gap (m), "
                             f"got force={show_value(self.force)}, gap={show_value(self.gap)}")
        if self.force is not None:
            field_bounded(self, "force", "N (point) or N/m (line)", *FORCE_RANGE)
        else:
            field_bounded(self, "gap", "m", *GAP_RANGE)


@dataclass(frozen=True, kw_only=True)
class Model:
    """Physics options.

    Parameters
    ----------
    elasticity : {"half-space", "local", "rigid"}
    cavitation : {"reynolds", "none"}
        ``reynolds``: p >= 0 with the complementarity condition; ``none``: full-Sommerfeld.
    thermal : {"none", "patch"}
    """

    _section = "model"
    elasticity: Literal["half-space", "local", "rigid"] = "half-space"
    cavitation: Literal["reynolds", "none"] = "reynolds"
    thermal: Literal["none", "patch"] = "none"

    def __post_init__(self) -> None:
        field_choice(self, "elasticity", ("half-space", "local", "rigid"))
        field_choice(self, "cavitation", ("reynolds", "none"))
        field_choice(self, "thermal", ("none", "patch"))


@dataclass(frozen=True, kw_only=True)
class MeshSpec:
    """Mesh options; every field optional (defaults come from the scene, see docs/scenes.md).

    Parameters
    ----------
    nodes : int or (int, int) or None
        Node count (line) or (nx, ny) (point).
    x_range, y_range : (float, float) or None
        Domain in units of the Hertz half-width (elastic scenes) or of sqrt(2 rx h0)
        (rigid scenes) [-].
    file : str or None
        A grid file (any meshio format; ``meshes/`` has examples) holding the nodes in
        those same units: a 1D mesh for a line contact, quads on a tensor grid for a point
        contact (uniform for elastic scenes: the half-space compliance needs it). It
        replaces ``nodes`` and the ranges. A relative path in a scene file is relative to
        that file.
    grading : {"uniform", "outlet"} or None
        Node spacing of an elastic (half-space) line contact under load: ``"uniform"``
        (the default, None) or ``"outlet"``: the grid refined around the outlet pressure
        spike, located by a solve on a coarse uniform grid first
        (:func:`bearing_fem.contacts.line.solve_line`); the node count of the uniform
        grid (rounded up to 4k + 1). Isothermal scenes; not with ``file``. ``"uniform"``
        is stored as None.
    target_error : float or None
        Largest estimated relative discretisation error [-] (0.05 is 5 %) of friction
        force, heat power, h_min and h_central, in [1e-3, 0.5]: a successful solve above
        it (or without an estimate of one of them) is solved again on the grid of half the
        spacing, until it meets it or the next grid would exceed 513^2 nodes (points) or
        8001 nodes (lines) (:func:`bearing_fem.contacts.refine.hold_target_error`). None
        (the default): one solve on the scene's grid. Not with ``file`` or a
        ``[transient]`` series.
    """

    _section = "mesh"
    nodes: int | tuple[int, int] | None = None
    x_range: tuple[float, float] | None = None
    y_range: tuple[float, float] | None = None
    file: str | None = None
    grading: str | None = None
    target_error: float | None = None

    def __post_init__(self) -> None:
        if self.grading is not None and (not isinstance(self.grading, str)
                                         or self.grading not in GRADINGS):
            raise SceneError(f"mesh.grading must be one of {', '.join(map(repr, GRADINGS))}, "
                             f"got {show_value(self.grading)}")
        if self.grading == "uniform":  # the default: one scene, one hash, one TOML
            object.__setattr__(self, "grading", None)
        if self.file is not None:
            self._check_file()
        n = self.nodes
        if n is not None:
            items = [plain_number(n)] if not isinstance(n, (list, tuple)) \
                else [plain_number(v) for v in n]
            if len(items) not in (1, 2) or any(isinstance(v, bool) or not isinstance(v, int)
                                                for v in items):
                raise SceneError(f"mesh.nodes must be an integer (line) or two integers "
                                 f"(point), got {show_value(n)}")
            if any(v < 9 or v > 20001 for v in items):
                raise SceneError(f"mesh.nodes must lie in [9, 20001] per direction, got "
                                 f"{show_value(n)}")
            object.__setattr__(self, "nodes", items[0] if len(items) == 1 and not
                               isinstance(n, (list, tuple)) else tuple(items))
        field_range(self, "x_range")
        field_range(self, "y_range")
        if self.target_error is not None:
            field_target_error(self)
            if self.file is not None:
                raise SceneError("mesh.target_error refines a generated grid (mesh.nodes and "
                                 "the ranges); it cannot refine mesh.file "
                                 f"{show_value(self.file)}: remove one of them")


    def _check_file(self) -> None:
        from .mesh import grid_axes

        f = self.file
        if not isinstance(f, str) or not f or "\x00" in f:
            raise SceneError(f"mesh.file must be a file name, got {show_value(f)}")
        given = [k for k in ("nodes", "x_range", "y_range", "grading")
                 if getattr(self, k) is not None]
        if given:
            raise SceneError(f"mesh.file replaces {', '.join('mesh.' + k for k in given)}: give "
                             "either the file or those keys")
        try:
            x, y = grid_axes(f)
        except ValueError as exc:
            raise SceneError(f"mesh.file: {exc}") from None
        for name, axis in (("x", x), ("y", y)):
            if axis is not None and not (axis[0] < 0.0 < axis[-1]):
                raise SceneError(f"mesh.file {f!r}: the {name} nodes must span 0 (start < 0 < "
                                 f"end, in Hertz semi-axes or sqrt(2 r h0)), got "
                                 f"[{axis[0]:g}, {axis[-1]:g}]")

    def axes(self) -> tuple[Any, Any] | None:
        """The node coordinates of ``file`` (x, and y or None), or None without a file."""
        if self.file is None:
            return None
        from .mesh import grid_axes

        return grid_axes(self.file)


@dataclass(frozen=True, kw_only=True)
class SolverSpec:
    """Nonlinear-solver settings.

    Parameters
    ----------
    tolerance : float
        Convergence tolerance on the scaled residual (infinity norm) [-].
    max_iterations : int
        Newton iterations allowed per continuation step.
    continuation : bool
        Fall back to continuation in the pressure-viscosity coefficient when a direct
        attempt stalls.
    iteration_budget : int
        Newton iterations allowed to the whole solve: every grid level, attempt and
        continuation step together. The solve stops with status ``budget_exhausted``
        when they are spent, and the message says what was spent.
    time_limit : float or None
        Wall-clock limit of the solve [s] (checked between Newton iterations), or None
        for no limit; status ``time_limit`` when it is reached.
    """

    _section = "solver"
    tolerance: float = 1e-8
    max_iterations: int = 50
    continuation: bool = True
    iteration_budget: int = 400
    time_limit: float | None = None

    def __post_init__(self) -> None:
        field_positive(self, "tolerance", "(dimensionless)")
        if self.tolerance >= 1e-1:
            raise SceneError(f"solver.tolerance must be < 0.1 (dimensionless), got {self.tolerance!r}")
        field_integer(self, "max_iterations", 1, 10000, "Newton iterations")
        field_bool(self, "continuation")
        field_integer(self, "iteration_budget", 1, 100000, "Newton iterations")
        if self.time_limit is not None:
            field_bounded(self, "time_limit", "s", 0.0, 1e6, open_low=True)


@dataclass(frozen=True, kw_only=True)
class Thermal:
    """Thermal coupling (``model.thermal = "patch"``; see ``docs/coupling.md``).

    Parameters
    ----------
    oil_temperature : float
        Bulk oil (and far-field body) temperature [deg C]. No default.
    exponent : float
        Prokofiev exponent n [-] of eta0(t) = eta_ref (t_ref/t)^n (Yachikov & Vostrikov 2015). No default.
    temperature_law : {"prokofiev"}
    reference_temperature : float
        t_ref [deg C] at which ``reference_viscosity`` (or ``lubricant.viscosity``) holds.
    reference_viscosity : float or None
        eta_ref [Pa s]; None: ``lubricant.viscosity`` is the value at t_ref.
    piezo_temperatures, piezo_values : (float, ...) or None
        Optional alpha(t) table: temperatures [deg C] (ascending) and alpha [1/Pa];
        ln(alpha) is interpolated linearly in t (and extrapolated), i.e.
        alpha = alpha_i exp(-beta (t - t_i)). None: ``lubricant.piezo`` at every t.
    conductivity, density, heat_capacity : float
        Body 1 lambda [W/(m K)], rho [kg/m^3], c [J/(kg K)] (bearing steel defaults).
    conductivity2, density2, heat_capacity2 : float or None
        Body 2 values; None: same as body 1.
    source_model : {"jaeger", "fe"}
        Flash temperature of each body: closed-form high-Peclet Jaeger integral, or the
        FE moving source (:func:`bearing_fem.physics.thermal.moving_source`).
    contact_temperature : {"mean", "max"}
        Which surface temperature rise sets eta0: the pressure-weighted mean or the maximum.
    max_iterations : int
        Fixed-point iterations allowed.
    tolerance : float
        Stop when the contact temperature changes by less than this [K].
    relaxation : float
        Under-relaxation factor omega in (0, 1] of the temperature update [-].
    max_temperature_rise : float
        A computed contact temperature rise above this [K] stops the loop with status
        ``diverged`` (e.g. Newtonian Barus traction under sliding: no physical fixed point).
    """

    _section = "thermal"
    oil_temperature: float
    exponent: float
    temperature_law: Literal["prokofiev"] = "prokofiev"
    reference_temperature: float = 40.0
    reference_viscosity: float | None = None
    piezo_temperatures: tuple[float, ...] | None = None
    piezo_values: tuple[float, ...] | None = None
    conductivity: float = 46.0
    density: float = 7850.0
    heat_capacity: float = 470.0
    conductivity2: float | None = None
    density2: float | None = None
    heat_capacity2: float | None = None
    source_model: Literal["jaeger", "fe"] = "jaeger"
    contact_temperature: Literal["mean", "max"] = "mean"
    max_iterations: int = 30
    tolerance: float = 0.05
    relaxation: float = 0.7
    max_temperature_rise: float = 300.0

    def __post_init__(self) -> None:
        t_lo, t_hi = TEMPERATURE_RANGE
        field_bounded(self, "oil_temperature", "deg C", t_lo, t_hi, open_low=True,
                 why="the Prokofiev law needs t > 0 deg C")
        field_bounded(self, "exponent", "(dimensionless)", 0.0, 20.0, open_low=True,
                 why="oils have 2..4")
        field_choice(self, "temperature_law", ("prokofiev",))
        field_bounded(self, "reference_temperature", "deg C", t_lo, t_hi, open_low=True)
        if self.reference_viscosity is not None:
            field_bounded(self, "reference_viscosity", "Pa s", *VISCOSITY_RANGE)
        for name, unit, lo, hi in (("conductivity", "W/(m K)", 1e-3, 1e4),
                                   ("density", "kg/m^3", 1.0, 1e5),
                                   ("heat_capacity", "J/(kg K)", 1.0, 1e5)):
            field_bounded(self, name, unit, lo, hi)
            if getattr(self, name + "2") is not None:
                field_bounded(self, name + "2", unit, lo, hi)
        field_choice(self, "source_model", ("jaeger", "fe"))
        field_choice(self, "contact_temperature", ("mean", "max"))
        field_piezo_table(self)
        field_integer(self, "max_iterations", 1, 1000, "fixed-point iterations")
        field_bounded(self, "tolerance", "K", 0.0, 100.0, open_low=True)
        field_bounded(self, "relaxation", "(dimensionless)", 0.0, 1.0, open_low=True)
        field_bounded(self, "max_temperature_rise", "K", 0.0, 1e4, open_low=True)


@dataclass(frozen=True, kw_only=True)
class Traction:
    """Shear (traction) model of the sliding (Couette) stress (``docs/theory.md``,
    "Traction").

    A scene without this section uses, where the surfaces slide, the generic mineral-oil
    model :data:`bearing_fem.physics.traction.GENERIC_MINERAL_OIL` and says so in the
    result's warnings.

    Parameters
    ----------
    model : {"eyring-limiting", "eyring", "limiting", "newtonian"}
        ``eyring-limiting`` tau = min(tau0 asinh(eta u_s/(h tau0)), tau_L0 + Lambda p)
        (default); ``eyring`` tau = tau0 asinh(eta u_s/(h tau0)); ``limiting``
        tau = min(eta u_s/h, tau_L0 + Lambda p); ``newtonian`` tau = eta u_s/h
        (unphysically large with Barus viscosity at GPa pressures: the result warns when
        its friction coefficient exceeds 0.2).
    eyring_stress : float
        Eyring stress tau0 [Pa] (mineral oils 2..10 MPa; default 5 MPa).
    limiting_shear_stress : float
        tau_L0 [Pa], the limiting shear stress at p = 0 (default 2 MPa).
    limiting_slope : float
        Lambda [-], pressure slope of the limiting shear stress (mineral oils 0.05..0.1;
        default 0.075).
    """

    _section = "traction"
    model: Literal["eyring-limiting", "eyring", "limiting", "newtonian"] = "eyring-limiting"
    eyring_stress: float = GENERIC_MINERAL_OIL["eyring_stress"]
    limiting_shear_stress: float = GENERIC_MINERAL_OIL["limiting_shear_stress"]
    limiting_slope: float = GENERIC_MINERAL_OIL["limiting_slope"]

    def __post_init__(self) -> None:
        field_choice(self, "model", TRACTION_MODELS)
        field_bounded(self, "eyring_stress", "Pa", 1e3, 1e10, why="oils have 2e6..1e7 Pa")
        field_bounded(self, "limiting_shear_stress", "Pa", 0.0, 1e10)
        field_bounded(self, "limiting_slope", "(dimensionless)", 0.0, 1.0,
                 why="oils have 0.05..0.1; above 1 the friction coefficient would exceed 1")
        if self.limiting_shear_stress == 0.0 and self.limiting_slope == 0.0:
            raise SceneError("traction: limiting_shear_stress (Pa) and limiting_slope (-) are "
                             "both 0: the limiting stress would vanish")


@dataclass(frozen=True, kw_only=True)
class Transient:
    """A squeeze series of a point contact with a prescribed gap: the rigid offset
    oscillates as h0(t) = h0 (1 + amplitude cos(omega t)), ``load.gap`` = h0 (the mean).

    ``bearing_fem.solve_series`` (and ``bearing-fem solve``) solve it: rigid scenes
    instant by instant (no memory), elastic ones with the time derivative of the film
    (``docs/point.md``, "Squeeze").

    Parameters
    ----------
    kind : {"squeeze"}
    amplitude : float
        eps [-], 0 <= eps < 1. No default.
    angular_frequency : float or None
        omega [rad/s]; None: u_m / sqrt(2 rx h0) (one hydrodynamic length per radian).
    steps : int
        Time steps per period (2..10000; default 32).
    periods : int
        Periods (1..100; default 1).
    scheme : {"bdf2", "euler", "quasi-steady"}
        Time discretisation of elastic scenes (default BDF2, second order); rigid scenes
        have no memory and are solved instant by instant whatever the scheme.
    """

    _section = "transient"
    kind: Literal["squeeze"] = "squeeze"
    amplitude: float
    angular_frequency: float | None = None
    steps: int = 32
    periods: int = 1
    scheme: Literal["bdf2", "euler", "quasi-steady"] = "bdf2"

    def __post_init__(self) -> None:
        field_choice(self, "kind", ("squeeze",))
        amp = field_number(self, "amplitude", "(dimensionless)")
        if not 0.0 <= amp < 1.0:
            raise SceneError(f"transient.amplitude must lie in [0, 1) (dimensionless: the gap "
                             f"would close), got {amp!r}")
        if self.angular_frequency is not None:
            field_bounded(self, "angular_frequency", "rad/s", 0.0, 1e9, open_low=True)
        field_integer(self, "steps", 2, 10000, "time steps per period")
        field_integer(self, "periods", 1, 100, "periods")
        field_choice(self, "scheme", ("bdf2", "euler", "quasi-steady"))


_SECTIONS: dict[str, type] = {
    "contact": Contact,
    "materials": Materials,
    "lubricant": Lubricant,
    "kinematics": Kinematics,
    "load": Load,
    "model": Model,
    "mesh": MeshSpec,
    "solver": SolverSpec,
    "thermal": Thermal,
    "traction": Traction,
    "transient": Transient,
}
_REQUIRED = ("contact", "lubricant", "kinematics", "load")
#: TOML table -> (attribute of Scene, section class): the same names.
_TABLES: dict[str, tuple[str, type]] = {name: (name, klass) for name, klass in _SECTIONS.items()}


@dataclass(frozen=True, kw_only=True)
class Scene:
    """A complete, validated contact scene (SI units). See ``docs/scenes.md``.

    Besides each section's own checks, a scene checks the rules between sections: the
    materials of an elastic scene, the thermal patch (its section, line contacts only,
    both surfaces moving), the mesh layout of the contact kind, and for an elastic scene
    with a load that its Hertz contact is small against the radii
    (:data:`MAX_HERTZ_RATIO`) and, unless it is a Barus half-space scene, that the
    viscosity at its Hertz pressure stays within double precision
    (:data:`MAX_VISCOSITY_RATIO`).
    """

    title: str = ""
    contact: Contact
    materials: Materials | None = None
    lubricant: Lubricant
    kinematics: Kinematics
    load: Load
    model: Model = field(default_factory=Model)
    mesh: MeshSpec = field(default_factory=MeshSpec)
    solver: SolverSpec = field(default_factory=SolverSpec)
    thermal: Thermal | None = None
    traction: Traction | None = None
    transient: Transient | None = None

    def __post_init__(self) -> None:
        _check_title(self.title)
        for name, klass in _SECTIONS.items():
            value = getattr(self, name)
            optional = name in ("materials", "thermal", "traction", "transient")
            if not isinstance(value, klass) and not (optional and value is None):
                raise SceneError(f"scene.{name} must be a {klass.__name__} (the [{name}] "
                                 f"section), got {show_value(value)}")
        if self.model.elasticity != "rigid" and self.materials is None:
            raise SceneError(f"materials are required for model.elasticity = "
                             f"{self.model.elasticity!r} (give e1, nu1, e2, nu2 in Pa, or "
                             "reduced_modulus in Pa)")
        if self.model.elasticity == "local" and self.load.force is None:
            raise SceneError("model.elasticity = 'local' (Kodnir) needs load.force (N/m): its "
                             "compliance A'/E depends on the load")
        if self.model.elasticity == "local" and self.contact.kind != "line":
            raise SceneError("model.elasticity = 'local' is defined for line contacts only, got "
                             f"contact.kind = {self.contact.kind!r}")
        nodes = self.mesh.nodes
        if nodes is not None:
            want_two = self.contact.kind == "point"
            if want_two != isinstance(nodes, tuple) or (want_two and len(nodes) != 2):
                raise SceneError(f"mesh.nodes must be {'[nx, ny]' if want_two else 'one integer'} "
                                 f"for a {self.contact.kind} contact, got {list(nodes) if isinstance(nodes, tuple) else nodes!r}")
        if self.mesh.grading == "outlet" and not (
                self.contact.kind == "line" and self.model.elasticity == "half-space"
                and self.load.force is not None):
            raise SceneError("mesh.grading = 'outlet' refines the grid at the outlet pressure "
                             "spike of an elastic line contact under load: it needs "
                             "contact.kind = 'line', model.elasticity = 'half-space' and "
                             f"load.force (N/m); got contact.kind = {self.contact.kind!r}, "
                             f"model.elasticity = {self.model.elasticity!r}"
                             + (", load.gap" if self.load.gap is not None else ""))
        if self.mesh.grading == "outlet" and self.model.thermal != "none":
            raise SceneError("mesh.grading = 'outlet' is not available with model.thermal = "
                             f"{self.model.thermal!r}: the thermal patch solves the film on "
                             "the uniform grid (remove mesh.grading, or model.thermal)")
        axes = self.mesh.axes()
        if axes is not None and (axes[1] is None) != (self.contact.kind == "line"):
            want = "a 1D mesh" if self.contact.kind == "line" else "quads on a tensor grid"
            raise SceneError(f"mesh.file {self.mesh.file!r}: a {self.contact.kind} contact "
                             f"needs {want}")
        self._check_thermal()
        self._check_transient()
        if self.mesh.y_range is not None and self.contact.kind == "line":
            raise SceneError("mesh.y_range applies to point contacts only")
        self._check_hertz()

    def _check_transient(self) -> None:
        """A squeeze series: point contacts with a prescribed gap, isothermal."""
        if self.transient is None:
            return
        if self.contact.kind != "point" or self.load.gap is None:
            raise SceneError("a [transient] squeeze series needs contact.kind = 'point' and "
                             "load.gap (m, the mean rigid offset h0 of h0(t)); got "
                             f"contact.kind = {self.contact.kind!r}, load.gap = "
                             f"{self.load.gap!r}")
        if self.model.thermal != "none":
            raise SceneError("a [transient] squeeze series is isothermal: model.thermal must "
                             f"be 'none', got {self.model.thermal!r}")
        if self.mesh.target_error is not None:
            raise SceneError("mesh.target_error applies to steady solves: a [transient] "
                             "squeeze series is solved on the scene's grid (remove "
                             "mesh.target_error, or give a finer mesh.nodes)")
        if self.model.elasticity == "rigid":
            lub = self.lubricant
            if lub.density != "incompressible" or (lub.viscosity_law == "roelands"
                                                   and self.model.cavitation != "reynolds"):
                raise SceneError("a rigid squeeze series is solved instant by instant on the "
                                 "linear path: it needs an incompressible lubricant with a "
                                 "constant or Barus viscosity law, or a Roelands law with "
                                 "model.cavitation = 'reynolds'")

    def _check_thermal(self) -> None:
        """The thermal patch: its section, line contacts only, both surfaces moving."""
        if self.model.thermal == "none":
            if self.thermal is not None:
                raise SceneError("a [thermal] section is given but model.thermal = 'none': it "
                                 "would be ignored; set model.thermal = 'patch' or remove the "
                                 "section")
            return
        if self.thermal is None:
            raise SceneError("model.thermal = 'patch' needs a [thermal] section (at least "
                             "thermal.oil_temperature in deg C and thermal.exponent)")
        if self.contact.kind != "line":
            raise SceneError("model.thermal = 'patch' applies to line contacts only (the "
                             "thermal patch couples a line-contact film to moving heat "
                             f"sources), got contact.kind = {self.contact.kind!r}")
        kin = self.kinematics
        if kin.u1 == 0.0 or kin.u2 == 0.0:
            raise SceneError("model.thermal = 'patch' needs both surface speeds non-zero (m/s): "
                             "the flash temperature of a surface is that of a moving heat "
                             f"source; got u1={kin.u1!r}, u2={kin.u2!r}")

    def hertz_scales(self) -> dict[str, Any] | None:
        """Hertz scales of an elastic scene with a load, or None (rigid, or a gap).

        Returns
        -------
        dict or None
            ``p_h`` the Hertz pressure [Pa] and ``widths``: one ``(what, width [m],
            radius name, radius [m])`` per semi-axis (b for a line contact; a_x, a_y for a
            point contact).
        """
        if (self.load.force is None or self.materials is None
                or self.model.elasticity == "rigid"):
            return None
        from . import units  # numpy/scipy only; imported here to keep scene imports light

        c, w = self.contact, self.load.force
        if c.kind == "line":
            b, p_h = units.hertz_line(w, c.rx, self.e_prime)
            return {"p_h": p_h, "widths": [("Hertz half-width b", b, "contact.rx", c.rx)]}
        hp = units.hertz_point(w, c.rx, c.ry, self.e_prime)
        return {"p_h": hp.p_h, "widths": [("Hertz semi-axis a_x", hp.a_x, "contact.rx", c.rx),
                                          ("Hertz semi-axis a_y", hp.a_y, "contact.ry", c.ry)]}

    def _check_hertz(self) -> None:
        """Elastic scenes with a load: the Hertz contact is small against the radii and
        the viscosity at the Hertz pressure stays within double precision."""
        hertz = self.hertz_scales()
        if hertz is None:
            return
        for name in ("x_range", "y_range"):
            if getattr(self.mesh, name) is not None:
                require_hertz_zone(f"mesh.{name}", getattr(self.mesh, name))
        w, p_h = self.load.force, hertz["p_h"]
        unit = "N/m" if self.contact.kind == "line" else "N"
        for what, width, radius_name, radius in hertz["widths"]:
            if width > MAX_HERTZ_RATIO * radius:
                raise SceneError(
                    f"load.force = {w!r} {unit} gives a {what} = {width:.4g} m, "
                    f"{width / radius:.3g} x {radius_name} = {radius!r} m (at most "
                    f"{MAX_HERTZ_RATIO:g}): Hertz theory and the half-space model need a "
                    f"contact small against the radii (Hertz pressure {p_h:.4g} Pa with "
                    f"E' = {self.e_prime:.4g} Pa); check the load and its unit")
        lub = self.lubricant
        if lub.viscosity_law == "barus" and self.model.elasticity == "half-space":
            # overflow-safe: the Reynolds equation of this path uses the reduced pressure,
            # where exp(-alpha p) underflows to 0 instead (MAX_VISCOSITY_RATIO)
            return
        eta = viscosity_function(lub.viscosity_law, lub.viscosity, lub.effective_piezo)
        with np.errstate(all="ignore"):
            ratio = float(np.asarray(eta(np.array([p_h])))[0]) / lub.viscosity
        if not ratio <= MAX_VISCOSITY_RATIO:
            raise SceneError(
                f"lubricant.piezo = {lub.piezo!r} 1/Pa ({lub.viscosity_law} law) at the Hertz "
                f"pressure {p_h:.4g} Pa raises the viscosity by more than "
                f"{MAX_VISCOSITY_RATIO:.3g} (alpha p_h = {lub.piezo * p_h:.4g}): beyond double "
                "precision; check the load and piezo")

    # ------------------------------------------------------------------------------
    @property
    def e_prime(self) -> float | None:
        """Reduced modulus E' [Pa], or None for a rigid scene without materials."""
        return None if self.materials is None else self.materials.e_prime

    @classmethod
    def from_dict(cls, data: Mapping[str, Any]) -> "Scene":
        """Build a scene from a nested mapping with the TOML layout (docs/scenes.md).

        Parameters
        ----------
        data : mapping
            ``{"contact": {...}, "lubricant": {...}, ...}``: section tables of keys in SI
            units (lengths in m, pressures in Pa, viscosities in Pa s, speeds in m/s).

        Returns
        -------
        Scene
            Validated.

        Raises
        ------
        SceneError
            An unknown section or key, a missing required one, or a value out of its
            range; the message names the field, the value and the unit.
        """
        hint = (" (this looks like a bearing file: run `bearing-fem bearing FILE`, or read "
                "it with bearing_fem.bearing.Bearing.from_toml)"
                if isinstance(data, Mapping) and "bearing" in data else "")
        if isinstance(data, Mapping):
            data = _plain_tree(data)   # numpy numbers (e.g. from np.linspace) as plain ones
        return cls(**sections_from_dict(data, _TABLES, _REQUIRED, "scene", hint))

    @classmethod
    def from_toml(cls, path: str | Path) -> "Scene":
        """Read and validate a TOML scene file.

        Parameters
        ----------
        path : str or Path
            A UTF-8 TOML file (a byte-order mark is accepted); a relative ``mesh.file``
            in it is relative to the file's folder (and stored as an absolute path).

        Returns
        -------
        Scene

        Raises
        ------
        SceneError
            An unreadable or malformed file, or an invalid scene (see :meth:`from_dict`).
        """
        path = Path(path)
        # absolute: the scene (stored in summary.json and result.h5) must name the grid
        # file wherever it is read back, not relative to the folder the solve ran in
        return cls.from_toml_string(read_text_file(path, "scene file"), source=str(path),
                                    base_dir=path.absolute().parent)

    @classmethod
    def from_toml_string(cls, text: str, source: str = "<string>",
                         base_dir: str | Path | None = None) -> "Scene":
        """Parse and validate a scene given as TOML text.

        Parameters
        ----------
        text : str
            TOML text with the layout of docs/scenes.md.
        source : str
            Name of the text in error messages.
        base_dir : str or Path, optional
            Folder that a relative ``mesh.file`` is taken relative to (the scene file's).

        Returns
        -------
        Scene

        Raises
        ------
        SceneError
            Malformed TOML (with the line), or an invalid scene (see :meth:`from_dict`).
        """
        data = parse_toml(text, source, "a scene")
        mesh = data.get("mesh")
        if (base_dir is not None and isinstance(mesh, dict) and isinstance(mesh.get("file"), str)
                and mesh["file"] and not Path(mesh["file"]).is_absolute()):
            mesh["file"] = str(Path(base_dir) / mesh["file"])
        return cls.from_dict(data)

    def to_dict(self) -> dict[str, Any]:
        """Nested dict with the TOML layout (None entries omitted); round-trips via from_dict."""
        return sections_to_dict(self, _TABLES)

    def replace(self, **sections: Any) -> "Scene":
        """Copy with whole sections replaced (``dataclasses.replace``)."""
        return replace(self, **sections)


def load_embedded(name: str) -> Scene:
    """Load one of the example scenes shipped in ``bearing_fem/scenes/`` (e.g. ``"roller"``)."""
    from importlib import resources

    files = resources.files("bearing_fem") / "scenes"
    available = sorted(p.name[:-5] for p in files.iterdir() if p.name.endswith(".toml"))
    if name not in available:
        raise SceneError(f"unknown embedded scene {name!r}; available: {', '.join(available)}")
    return Scene.from_toml_string((files / f"{name}.toml").read_text(encoding="utf-8"),
                                  source=f"embedded scene {name!r}")
