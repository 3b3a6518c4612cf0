"""Progress bars (tqdm) for sweeps and for long single solves.

Both draw on stderr only when it is a terminal (or when ``enabled=True`` is forced) and
never otherwise, so logs, pipes and CI output stay clean; the command line turns them
off with ``--quiet``. Logging (``-v``) is independent of them.

* :class:`SweepProgress`: cases done out of the total, failures so far and the time left.
* :class:`SolveProgress`: the callback of :func:`bearing_fem.solve` (``progress=``):
  one bar per grid level with the Newton iteration count and the last residual.
"""
from __future__ import annotations

import sys
from typing import Any, Mapping, TextIO


def is_terminal(stream: Any) -> bool:
    """True when ``stream`` is an interactive terminal."""
    try:
        return bool(stream.isatty())
    except (AttributeError, ValueError):  # no isatty, or a closed stream
        return False


def _enabled(enabled: bool | None, file: TextIO) -> bool:
    return is_terminal(file) if enabled is None else bool(enabled)


class SweepProgress:
    """A bar over the cases of a sweep: done/total, failures, elapsed and time left.

    Parameters
    ----------
    total : int
        Cases to run.
    enabled : bool or None
        None: draw only when ``file`` is a terminal; False: never; True: always.
    file : text stream, optional
        Default ``sys.stderr``.
    desc : str
    """

    def __init__(self, total: int, *, enabled: bool | None = None, file: TextIO | None = None,
                 desc: str = "sweep") -> None:
        from tqdm import tqdm

        self.file = sys.stderr if file is None else file
        self.enabled = _enabled(enabled, self.file) and total > 0
        self.total = int(total)
        self.done = 0
        self.failures = 0
        self.bar = tqdm(total=self.total, desc=desc, unit="case", file=self.file,
                        disable=not self.enabled, dynamic_ncols=True, smoothing=0.05,
                        mininterval=0.2)

    def update(self, outcome: Mapping[str, Any]) -> None:
        """Count one finished case (``outcome["success"]`` False counts as a failure)."""
        self.done += 1
        if not outcome.get("success"):
            self.failures += 1
        self.bar.set_postfix(failed=self.failures, refresh=False)
        self.bar.update(1)

    def close(self) -> None:
        """Finish the bar (idempotent)."""
        self.bar.close()

    def __enter__(self) -> "SweepProgress":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


class SolveProgress:
    """Progress callback of one solve: ``bearing_fem.solve(scene, progress=SolveProgress())``.

    Events (dicts) from the solver: ``{"event": "level", "level": i, "levels": n, "grid":
    "257x257"}`` when a grid level starts, ``{"event": "newton", "level": i, "iteration":
    k, "residual": r}`` after each Newton iteration. Each level gets a bar labelled with
    its grid and index; each Newton iteration advances it and shows the scaled residual.
    Other events are ignored.

    Parameters
    ----------
    enabled : bool or None
        None: draw only when ``file`` is a terminal; False: never; True: always.
    file : text stream, optional
        Default ``sys.stderr``.
    desc : str
        Prefix of the bar's label (e.g. the scene's title).

    Attributes
    ----------
    levels_started : int
    iterations : int
        Newton iterations seen over all levels.
    last_residual : float or None
    grid : str or None
        Label of the current level's grid.
    """

    def __init__(self, *, enabled: bool | None = None, file: TextIO | None = None,
                 desc: str = "solve") -> None:
        self.file = sys.stderr if file is None else file
        self.enabled = _enabled(enabled, self.file)
        self.desc = desc
        self.bar = None
        self.levels_started = 0
        self.iterations = 0
        self.last_residual: float | None = None
        self.grid: str | None = None

    def _new_bar(self, label: str) -> None:
        from tqdm import tqdm

        self._close_bar()
        self.bar = tqdm(total=None, desc=label, unit="it", file=self.file,
                        disable=not self.enabled, dynamic_ncols=True, leave=False,
                        mininterval=0.1)

    def _close_bar(self) -> None:
        if self.bar is not None:
            self.bar.refresh()  # the level's last iteration and residual, once
            self.bar.close()
            self.bar = None

    def __call__(self, event: Mapping[str, Any]) -> None:
        kind = event.get("event")
        if kind == "level":
            self.levels_started += 1
            self.grid = str(event.get("grid", "?"))
            i, n = int(event.get("level", 0)), event.get("levels")
            where = f"level {i + 1}/{n}" if n else f"level {i + 1}"
            self._new_bar(f"{self.desc}: grid {self.grid} ({where})")
        elif kind == "newton":
            if self.bar is None:
                self._new_bar(f"{self.desc}: level {int(event.get('level', 0)) + 1}")
            self.iterations += 1
            r = event.get("residual")
            self.last_residual = None if r is None else float(r)
            if r is not None:
                self.bar.set_postfix_str(f"Newton {event.get('iteration', '?')}, residual "
                                         f"{float(r):.2e}", refresh=False)
            self.bar.update(1)

    def close(self) -> None:
        """Remove the bar of the last level (idempotent)."""
        self._close_bar()

    def __enter__(self) -> "SolveProgress":
        return self

    def __exit__(self, *exc: Any) -> None:
        self.close()


def solve_progress(quiet: bool = False, *, file: TextIO | None = None,
                   desc: str = "solve") -> SolveProgress | None:
    """The progress callback the command line passes to a solve.

    Parameters
    ----------
    quiet : bool
        No progress at all (``-q``).
    file : text stream, optional
        Where to draw (default ``sys.stderr``).
    desc : str
        The bar's label.

    Returns
    -------
    SolveProgress or None
        None when ``quiet`` or when ``file`` is not a terminal.
    """
    stream = sys.stderr if file is None else file
    if quiet or not is_terminal(stream):
        return None
    return SolveProgress(enabled=True, file=stream, desc=desc)
