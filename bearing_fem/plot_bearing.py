"""Figures of a bearing result (matplotlib, Agg backend; imported only when plotting).

* :func:`plot_load_distribution` - element load (and contact angle for ball bearings)
  over azimuth, with the load zone;
* :func:`plot_films` - minimum film and maximum pressure of every loaded element's inner
  and outer contact over azimuth;
* :func:`plot_torque_comparison` - EHL friction torque (inner and outer contacts) beside
  the empirical models (when contacts failed: no EHL bar, and the figure says how many);
* :func:`write_figures` - all three into a directory (each written under a temporary
  name and moved into place).
"""
from __future__ import annotations

import math
import os
import secrets
from pathlib import Path
from typing import TYPE_CHECKING, Any

import numpy as np

if TYPE_CHECKING:  # annotations only: matplotlib is imported when plotting
    from matplotlib.figure import Figure

    from .bearing.solve import BearingResult

__all__ = ["plot_load_distribution", "plot_films", "plot_torque_comparison", "torque_figure",
           "failed_contacts", "films_figure", "write_figures", "FIGURES"]

#: Figure files of :func:`write_figures`, keyed as returned.
FIGURES = {"load_distribution": "load_distribution.png", "films": "films_pressures.png",
           "torque": "torque_comparison.png"}


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig: Any, path: str | Path) -> Path:
    """Lay out ``fig``, write it to ``path`` (PNG, 120 dpi) under a temporary name moved
    into place, and close it (also when writing fails)."""
    plt = _pyplot()
    path = Path(path)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.{secrets.token_hex(4)}.tmp.png")
    try:
        fig.tight_layout()
        path.parent.mkdir(parents=True, exist_ok=True)
        fig.savefig(tmp, dpi=120)
        os.replace(tmp, path)
    finally:
        plt.close(fig)
        if tmp.exists():
            tmp.unlink()
    return path


def _element_arrays(result: Any, row: int = 0) -> dict[str, np.ndarray]:
    el = [e for e in result.elements if e["row"] == row]
    order = np.argsort([e["azimuth_deg"] for e in el])
    el = [el[i] for i in order]

    def col(fn):
        return np.array([np.nan if fn(e) is None else fn(e) for e in el], dtype=float)

    return {"psi": col(lambda e: e["azimuth_deg"]), "load": col(lambda e: e["load"]),
            "load_outer": col(lambda e: e["load_outer"]),
            "alpha": col(lambda e: e["contact_angle_deg"]),
            "hmin_i": col(lambda e: e["inner"]["h_min"]),
            "hmin_o": col(lambda e: e["outer"]["h_min"]),
            "pmax_i": col(lambda e: e["inner"]["p_max"]),
            "pmax_o": col(lambda e: e["outer"]["p_max"])}


#: Smallest span of the contact-angle axis of the load figure [deg] (a radially loaded
#: deep-groove bearing's angles vary by hundredths of a degree).
MIN_ANGLE_SPAN = 2.0


def _opposed_row(result: Any) -> dict[str, np.ndarray] | None:
    """The element arrays of the second row when its loads differ from the first row's
    (opposed tapered rows under an axial load), else None (identical rows: one shown).

    Parameters
    ----------
    result : BearingResult
        A solved bearing (:func:`bearing_fem.bearing.solve_bearing`).

    Returns
    -------
    dict or None
        Per-element arrays of row 1 (azimuth [deg], loads [N], films [m], pressures
        [Pa]), ordered by azimuth.
    """
    if result.bearing.geometry.rows < 2:
        return None
    first, second = _element_arrays(result, 0), _element_arrays(result, 1)
    if np.allclose(first["load"], second["load"], rtol=1e-9, atol=0.0):
        return None
    return second


def plot_load_distribution(result: Any, path: str | Path) -> Path:
    """Element loads [N] over azimuth [deg] (row 0, and the opposed row where it differs);
    contact angles for ball bearings."""
    plt = _pyplot()
    a = _element_arrays(result)
    fig, ax = plt.subplots(figsize=(7, 4))
    other = _opposed_row(result)
    ax.bar(a["psi"], a["load"], width=0.6 * 360.0 / max(len(a["psi"]), 1), color="C0",
           label="inner contact load" + (", row 0" if other is not None else ""))
    if np.any(a["load_outer"] != a["load"]):
        ax.plot(a["psi"], a["load_outer"], "o", color="C3", label="outer contact load")
    if other is not None:
        ax.plot(other["psi"], other["load"], "D", color="C1", ms=5,
                label="inner contact load, row 1 (opposed)")
    half = math.degrees(result.distribution.load_zone_half_angle)
    if half < 180.0:
        ax.axvspan(-half, half, color="C0", alpha=0.08, label=f"load zone +-{half:.1f} deg")
    ax.set_xlabel("azimuth psi [deg] (radial load at 0)")
    ax.set_ylabel("element load Q [N]")
    ax.set_xlim(-180, 180)
    if result.bearing.geometry.is_ball:
        ax2 = ax.twinx()
        ax2.plot(a["psi"], a["alpha"], "s--", color="C2", ms=4, label="contact angle")
        ax2.set_ylabel("contact angle [deg]", color="C2")
        lo, hi = float(np.min(a["alpha"])), float(np.max(a["alpha"]))
        if hi - lo < MIN_ANGLE_SPAN:  # a nearly constant angle: no magnified noise axis
            mid = 0.5 * (lo + hi)
            ax2.set_ylim(mid - 0.5 * MIN_ANGLE_SPAN, mid + 0.5 * MIN_ANGLE_SPAN)
    ax.legend(loc="upper right", fontsize=8)
    ax.set_title(result.bearing.title or result.bearing.geometry.type, fontsize=10)
    return _save(fig, path)


def films_figure(result: BearingResult) -> Figure:
    """The figure of :func:`plot_films`, not saved (the caller closes it).

    Failed contacts have no film or pressure (no point); the title then says "EHL: k of
    n contacts failed", and when every contact failed the empty axes carry that note.

    Parameters
    ----------
    result : BearingResult
        A solved bearing (:func:`bearing_fem.bearing.solve_bearing`).

    Returns
    -------
    matplotlib.figure.Figure
        Two axes over the azimuth [deg]: h_min [um] and p_max [GPa] of the inner and
        outer contacts of the first row, and of the opposed row where its loads differ
        (tapered rows under an axial load).
    """
    plt = _pyplot()
    a = _element_arrays(result)
    fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(7, 5.5), sharex=True)
    other = _opposed_row(result)
    first = ", row 0" if other is not None else ""   # the row numbers of elements.csv
    for key, lab, mk in (("hmin_i", "inner", "o-"), ("hmin_o", "outer", "s-")):
        ax1.plot(a["psi"], a[key] * 1e6, mk, label=lab + first)
    for key, lab, mk in (("pmax_i", "inner", "o-"), ("pmax_o", "outer", "s-")):
        ax2.plot(a["psi"], a[key] * 1e-9, mk, label=lab + first)
    if other is not None:  # the opposed row's loaded elements (no result elsewhere: NaN)
        for ax, key, scale in ((ax1, "hmin_i", 1e6), (ax1, "hmin_o", 1e6),
                               (ax2, "pmax_i", 1e-9), (ax2, "pmax_o", 1e-9)):
            side = "inner" if key.endswith("_i") else "outer"
            ax.plot(other["psi"], other[key] * scale, "o--" if side == "inner" else "s--",
                    mfc="none", label=f"{side}, row 1 (opposed)")
    ax1.set_ylabel("h_min [um]")
    ax2.set_ylabel("p_max [GPa]")
    ax2.set_xlabel("azimuth psi [deg]")
    title = "EHL films and pressures of the loaded elements"
    bad, n = failed_contacts(result)
    if bad:
        note = f"EHL: {bad} of {n} contacts failed"
        title += f"\n{note} (no film or pressure shown for them)"
        if bad == n:
            for ax in (ax1, ax2):
                ax.text(0.5, 0.5, f"no EHL result:\n{note.removeprefix('EHL: ')}\n(status "
                        f"{result.status})", transform=ax.transAxes, ha="center",
                        va="center", fontsize=9, color="C3")
    if any(line.get_label() and not line.get_label().startswith("_") for line in ax1.lines) \
            and bad < n:
        ax1.legend(fontsize=8)
    ax1.set_title(title, fontsize=10)
    return fig


def plot_films(result: Any, path: str | Path) -> Path:
    """Minimum film [um] and maximum pressure [GPa] per element (row 0, and the opposed
    row where its loads differ) over azimuth (:func:`films_figure`)."""
    return _save(films_figure(result), path)


def failed_contacts(result: BearingResult) -> tuple[int, int]:
    """How many of a bearing result's solved contacts were unsuccessful.

    Parameters
    ----------
    result : BearingResult
        A solved bearing (:func:`bearing_fem.bearing.solve_bearing`).

    Returns
    -------
    failed, solved : int
        Unsuccessful contacts, and contacts solved (not excluded as lightly loaded).
    """
    contacts = [c for e in result.elements for c in (e["inner"], e["outer"])
                if c["status"] != "excluded"]
    return sum(1 for c in contacts if not c["success"]), len(contacts)


def torque_figure(result: BearingResult) -> Figure:
    """The figure of :func:`plot_torque_comparison`, not saved (the caller closes it).

    Without an EHL total (a contact failed) there is no EHL bar: its place is labelled
    "EHL: k of n contacts failed" and a note on the axes says so.

    Parameters
    ----------
    result : BearingResult
        A solved bearing (:func:`bearing_fem.bearing.solve_bearing`).

    Returns
    -------
    matplotlib.figure.Figure
        Bars of the friction torque [N m]: the EHL total (inner and outer contacts) beside
        the empirical models.
    """
    plt = _pyplot()
    t = result.totals
    names, vals = [], []
    fig, ax = plt.subplots(figsize=(7, 4))
    if t.get("friction_torque") is None:
        bad, n = failed_contacts(result)
        label = (f"EHL: {bad} of {n} contacts failed" if bad else "EHL: no total")
        ax.bar([label], [0.0], color="none", edgecolor="C3", hatch="//")
        ax.text(0, 0, f"no EHL torque:\n{label.removeprefix('EHL: ')}\n(status "
                f"{result.status})", ha="center", va="bottom", fontsize=9, color="C3")
    else:
        ax.bar(["EHL (this solve)"], [t["friction_torque_inner"]], color="C0", label="inner")
        ax.bar(["EHL (this solve)"], [t["friction_torque_outer"]],
               bottom=[t["friction_torque_inner"]], color="C1", label="outer")
        rel = (t.get("error_estimate") or {}).get("friction_torque")
        if rel is not None:  # the estimated discretisation error of the total
            ax.errorbar(["EHL (this solve)"], [t["friction_torque"]],
                        yerr=[abs(t["friction_torque"]) * rel], fmt="none", ecolor="k",
                        capsize=6, label=f"estimated error {100 * rel:.2g} %")
    for name, m in result.empirical.items():
        if m.get("torque") is not None:
            names.append(name.replace("_", " "))
            vals.append(m["torque"])
    ax.bar(names, vals, color="0.6", label="empirical")
    ax.set_ylabel("friction torque [N m]")
    ax.set_ylim(top=ax.get_ylim()[1] * 1.3)  # head room: the legend does not hide a bar
    ax.legend(fontsize=8, loc="upper left", ncol=2)
    ax.set_title("EHL torque (rolling losses only) vs empirical models", fontsize=10)
    plt.setp(ax.get_xticklabels(), rotation=15, fontsize=8)
    return fig


def plot_torque_comparison(result: Any, path: str | Path) -> Path:
    """Bar chart: EHL friction torque (inner + outer contacts, with its estimated
    discretisation error as an error bar) and the empirical models; when contacts
    failed, no EHL bar and a note "EHL: k of n contacts failed" (:func:`torque_figure`)."""
    return _save(torque_figure(result), path)


def write_figures(result: Any, outdir: str | Path) -> dict[str, Path]:
    """All bearing figures into ``outdir`` (:data:`FIGURES`); nothing for a result
    without a load distribution."""
    outdir = Path(outdir)
    if result.distribution is None:
        return {}
    return {"load_distribution": plot_load_distribution(result,
                                                        outdir / FIGURES["load_distribution"]),
            "films": plot_films(result, outdir / FIGURES["films"]),
            "torque": plot_torque_comparison(result, outdir / FIGURES["torque"])}
