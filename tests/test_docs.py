"""The docs name only what exists, and the repository stands alone.

Every dotted ``bearing_fem.a.b`` name in docs/*.md and README.md must import or resolve as
an attribute, every ``bf.name`` must be an attribute of the package, and every name listed
under a ``### `bearing_fem.module``` heading of docs/api.md must exist in that module. A
renamed or moved function then fails here instead of leaving a dead name in the docs.
"""
from __future__ import annotations

import importlib
import math
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PAGES = sorted((ROOT / "docs").glob("*.md")) + [ROOT / "README.md"]
DOTTED = re.compile(r"\bbearing_fem(?:\.[A-Za-z_][A-Za-z0-9_]*)+")
BF_NAME = re.compile(r"`bf\.([A-Za-z_][A-Za-z0-9_]*)")
API_HEADING = re.compile(r"^### `(bearing_fem(?:\.[A-Za-z_][A-Za-z0-9_]*)*)`")
API_BULLET = re.compile(r"^- `([A-Za-z_][A-Za-z0-9_.]*)")


def resolve(dotted: str) -> bool:
    """True if ``dotted`` is a module or an attribute chain starting at a module."""
    parts = dotted.split(".")
    for k in range(len(parts), 0, -1):
        try:
            obj = importlib.import_module(".".join(parts[:k]))
        except ModuleNotFoundError:
            continue
        for name in parts[k:]:
            if not hasattr(obj, name):
                return False
            obj = getattr(obj, name)
        return True
    return False


def _names(pattern: re.Pattern[str]) -> list[tuple[str, int, str]]:
    found = []
    for page in PAGES:
        for n, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            found += [(page.name, n, m.group(0)) for m in pattern.finditer(line)]
    return found


def test_dotted_names_in_docs_resolve():
    names = _names(DOTTED)
    assert len(names) > 50, "the docs should name the package's modules (pattern broken?)"
    bad = [f"{page}:{n}: {name}" for page, n, name in names if not resolve(name)]
    assert not bad, "names in the docs that do not exist:\n" + "\n".join(bad)


def test_bf_names_in_docs_resolve():
    import bearing_fem as bf

    names = [(p, n, m) for p, n, m in _names(BF_NAME)]
    assert names, "the docs should show the bf.* API"
    bad = [f"{page}:{n}: {text}" for page, n, text in names
           if not hasattr(bf, text.removeprefix("`bf."))]
    assert not bad, "bf.* names in the docs that the package does not have:\n" + "\n".join(bad)


def test_api_page_lists_existing_names():
    module = None
    checked, bad = 0, []
    for n, line in enumerate((ROOT / "docs" / "api.md").read_text(encoding="utf-8")
                             .splitlines(), 1):
        head = API_HEADING.match(line)
        if head:
            module = head.group(1)
            continue
        if line.startswith("## "):
            module = None
        bullet = API_BULLET.match(line)
        if module is None or not bullet or bullet.group(1).startswith("bearing_fem"):
            continue
        checked += 1
        if not resolve(f"{module}.{bullet.group(1)}"):
            bad.append(f"api.md:{n}: {module}.{bullet.group(1)}")
    assert checked > 100, f"only {checked} api.md entries checked (format changed?)"
    assert not bad, "api.md lists names that do not exist:\n" + "\n".join(bad)


@pytest.mark.parametrize("pattern", [re.compile(r"/(?:work|root|home)/\w")])
def test_repository_stands_alone(pattern):
    """No reference a user cannot follow (machine paths)."""
    suffixes = {".py", ".md", ".toml", ".txt", ".cfg", ".yml", ".yaml"}
    files = [p for p in ROOT.rglob("*") if p.is_file() and p.suffix in suffixes
             and not any(part.startswith(".") or part in ("build", "dist", "out")
                         or part.endswith(".egg-info") for part in p.relative_to(ROOT).parts)]
    assert len(files) > 50, "the walk should see the package, tests, studies and docs"
    this = Path(__file__).resolve()
    bad = [f"{p.relative_to(ROOT)}:{n}: {line.strip()[:80]}"
           for p in files if p.resolve() != this
           for n, line in enumerate(p.read_text(encoding="utf-8", errors="replace")
                                    .splitlines(), 1)
           if pattern.search(line)]
    assert not bad, "references a user of the repository cannot follow:\n" + "\n".join(bad)


def _heading_anchors(page: Path) -> set[str]:
    """GitHub's anchors of a Markdown page's headings (lower case, punctuation but - and _
    dropped, spaces to hyphens; a repeated heading gets -1, -2, ...); code blocks
    skipped."""
    out: set[str] = set()
    seen: dict[str, int] = {}
    fenced = False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        heading = None if fenced else re.match(r"#{1,6}\s+(.*)", line)
        if heading:
            slug = re.sub(r"[^\w\- ]", "", heading.group(1).strip().lower()).replace(" ", "-")
            k = seen.get(slug, 0)
            seen[slug] = k + 1
            out.add(slug if k == 0 else f"{slug}-{k}")
    return out


def test_section_links_resolve():
    """Every link to a section (``page.md#anchor`` or ``#anchor``) in the README and the
    docs names a heading of that page."""
    pages = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
    checked, bad = 0, []
    for page in pages:
        text = page.read_text(encoding="utf-8")
        for m in re.finditer(r"\]\(((?!https?:)[^)\s]*?)#([^)\s]+)\)", text):
            target = page.parent / m.group(1) if m.group(1) else page
            checked += 1
            if not target.is_file() or m.group(2) not in _heading_anchors(target):
                bad.append(f"{page.relative_to(ROOT)}: {m.group(0)}")
    assert checked >= 5, f"only {checked} section links found (pattern changed?)"
    assert not bad, "links to sections that do not exist:\n" + "\n".join(bad)


# ---------------------------------------------------------------------------------------
# Cross-references by section number or name, short module names, documented constants,
# and the calls and signatures shown in code.
# ---------------------------------------------------------------------------------------
SOURCES = [*PAGES, *sorted((ROOT / "bearing_fem").rglob("*.py")),
           *sorted((ROOT / "bearing_fem").rglob("*.toml")),
           *sorted((ROOT / "studies").glob("*.py")), *sorted((ROOT / "tests").glob("*.py"))]


def _headings(page: Path) -> list[str]:
    """The heading texts of a Markdown page (code blocks skipped)."""
    out, fenced = [], False
    for line in page.read_text(encoding="utf-8").splitlines():
        if line.startswith("```"):
            fenced = not fenced
        heading = None if fenced else re.match(r"#{1,6}\s+(.*)", line)
        if heading:
            out.append(heading.group(1).strip())
    return out


def _numbers(page: Path) -> set[str]:
    """Section numbers of a page's headings ("6.6", "4.2b", "14")."""
    return {m.group(1) for h in _headings(page)
            if (m := re.match(r"([0-9]+(?:\.[0-9]+)*[a-z]?)[.\s]", h + " "))}


def test_numbered_section_references_resolve():
    """A page and a section number (``bearing.md, section 5.3``) in the docs, the
    package, the studies and the tests name a numbered heading of that page (speed.md and
    line_contact.md cited a section "6.4b" of the theory page, which has none)."""
    pattern = re.compile(r"\b([a-z_]+)\.md\)?,? (?:section |sections |sec\. )?"
                         r"([0-9]+(?:\.[0-9]+)?[a-z]?)\b")
    checked, bad = 0, []
    for source in SOURCES:
        text = source.read_text(encoding="utf-8")
        for n, line in enumerate(text.splitlines(), 1):
            for m in pattern.finditer(line):
                page = ROOT / "docs" / f"{m.group(1)}.md"
                if not page.is_file() or not _numbers(page):
                    continue
                checked += 1
                if m.group(2) not in _numbers(page):
                    bad.append(f"{source.relative_to(ROOT)}:{n}: {m.group(0)}")
    assert checked > 100, f"only {checked} numbered section references found (pattern?)"
    assert not bad, "references to section numbers that do not exist:\n" + "\n".join(bad)


def test_named_section_references_resolve():
    """``page.md, "Heading"`` names a heading of that page (or the label a paragraph of it
    starts with)."""
    pattern = re.compile(r"\b([a-z_]+)\.md\)?,? \(?\"([^\"]+)\"")
    checked, bad = 0, []
    for source in (s for s in SOURCES if s.resolve() != Path(__file__).resolve()):
        text = " ".join(source.read_text(encoding="utf-8").split())
        for m in pattern.finditer(text):
            page = ROOT / "docs" / f"{m.group(1)}.md"
            if not page.is_file():
                continue
            checked += 1
            name = m.group(2).lower()
            lines = [line.strip().lstrip("*").lower()
                     for line in page.read_text(encoding="utf-8").splitlines()]
            if not (any(name in h.lower() for h in _headings(page))
                    or any(line.startswith(name) for line in lines)):
                bad.append(f"{source.relative_to(ROOT)}: {m.group(0)}")
    assert checked >= 10, f"only {checked} named section references found (pattern?)"
    assert not bad, "references to sections that do not exist:\n" + "\n".join(bad)


#: Short module names the docs use in code spans (`line.COARSEST_NODES`); names that are
#: also scene sections (mesh, thermal, traction, kinematics) are not checked here.
SHORT_MODULES = {
    "line": "bearing_fem.contacts.line", "point": "bearing_fem.contacts.point",
    "driver": "bearing_fem.contacts.driver", "dispatch": "bearing_fem.contacts.dispatch",
    "transient": "bearing_fem.contacts.transient", "series": "bearing_fem.contacts.series",
    "coupling": "bearing_fem.contacts.coupling", "kodnir": "bearing_fem.contacts.kodnir",
    "newton": "bearing_fem.numerics.newton", "fe": "bearing_fem.numerics.fe",
    "elasticity": "bearing_fem.physics.elasticity", "reynolds": "bearing_fem.physics.reynolds",
    "rheology": "bearing_fem.physics.rheology", "post": "bearing_fem.post",
    "units": "bearing_fem.units", "analytic": "bearing_fem.analytic",
    "formulas": "bearing_fem.formulas", "checks": "bearing_fem.checks",
    "contacts": "bearing_fem.contacts", "numerics": "bearing_fem.numerics",
    "physics": "bearing_fem.physics", "sweep": "bearing_fem.sweep",
}
FILE_SUFFIXES = {"py", "vtm", "vtu", "toml", "csv", "json", "png", "h5", "md", "sqlite"}


def test_short_module_references_resolve():
    """`line.REDUCED_POISEUILLE_LINE`, `point.WARM_START_ALPHA`, ... name attributes of
    those modules, and `solver.key` a key of the [solver] section (line_contact.md named a
    `solver.REDUCED_POISEUILLE_LINE` that exists nowhere)."""
    from dataclasses import fields

    from bearing_fem.scene import SolverSpec

    solver_keys = {f.name for f in fields(SolverSpec)}
    pattern = re.compile(r"`([a-z_]+)\.([A-Za-z_][A-Za-z0-9_]*(?:\.[A-Za-z_][A-Za-z0-9_]*)*)`")
    checked, bad = 0, []
    for page in PAGES:
        for n, line in enumerate(page.read_text(encoding="utf-8").splitlines(), 1):
            for m in pattern.finditer(line):
                prefix, rest = m.groups()
                if rest.rsplit(".", 1)[-1] in FILE_SUFFIXES:
                    continue
                if prefix == "solver":
                    ok = rest in solver_keys
                elif prefix in SHORT_MODULES:
                    ok = resolve(f"{SHORT_MODULES[prefix]}.{rest}")
                else:
                    continue
                checked += 1
                if not ok:
                    bad.append(f"{page.name}:{n}: {m.group(0)}")
    assert checked > 60, f"only {checked} short references found (pattern changed?)"
    assert not bad, "short names in the docs that do not exist:\n" + "\n".join(bad)


def _module(name: str):
    return importlib.import_module(name)


#: (page, pattern whose groups are numbers or words the page states, the code's values in
#: the same order). A number written in the docs that is a constant of the code is
#: checked here, so that changing the constant fails until the page says so.
DOCUMENTED_CONSTANTS = [
    # line solver: Newton steps with the dense Jacobian (theory.md 6.6)
    ("theory.md", r"eta_k = max\(([0-9.e+-]+), EW_k\)\s+within ([0-9]+) iterations",
     lambda: (_module("bearing_fem.contacts.line").REUSE_GMRES_RTOL,
              _module("bearing_fem.contacts.line").REUSE_GMRES_ITERATIONS)),
    ("theory.md", r"capped at ([0-9.e+-]+) \(`line\.REUSE_GMRES_FORCING`",
     lambda: (_module("bearing_fem.contacts.line").REUSE_GMRES_FORCING_MAX
              if _module("bearing_fem.contacts.line").REUSE_GMRES_FORCING else None,)),
    ("theory.md", r"`line\.DENSE_LU_SINGLE`",
     lambda: () if _module("bearing_fem.contacts.line").DENSE_LU_SINGLE else (None,)),
    ("theory.md", r"by FFT from ([0-9]+) nodes",
     lambda: (_module("bearing_fem.physics.elasticity").LINE_FFT_APPLY_MIN,)),
    # point solver: inexact Newton-Krylov steps (point.md)
    ("point.md", r"eta_k = min\(([0-9.e+-]+), max\(([0-9.e+-]+), EW_k, ([0-9.e+-]+) tol",
     lambda: (_module("bearing_fem.contacts.point").GMRES_FORCING_MAX,
              _module("bearing_fem.contacts.point").GMRES_RTOL,
              _module("bearing_fem.contacts.point").GMRES_TOLERANCE_FRACTION)),
    ("point.md", r"`GMRES_FORCING = \"([a-z-]+)\"`",
     lambda: (_module("bearing_fem.contacts.point").GMRES_FORCING,)),
    ("point.md", r"incomplete \(drop tolerance\s+([0-9.e+-]+), `PRECONDITIONER_DROP_TOL`",
     lambda: (_module("bearing_fem.contacts.point").PRECONDITIONER_DROP_TOL,)),
    ("point.md", r"at most ([0-9]+) iterations with it \(([0-9]+) from ([0-9]+) free nodes",
     lambda: (_module("bearing_fem.contacts.point").PRECONDITIONER_KEEP_ITERATIONS,
              _module("bearing_fem.contacts.point").PRECONDITIONER_KEEP_ITERATIONS_LARGE,
              _module("bearing_fem.contacts.point").PRECONDITIONER_LARGE_UNKNOWNS)),
    ("elasticity.md", r"up to ([0-9]+) nodes, `LINE_DENSE_AUTO_CAP`\) builds it\s+at "
     r"construction and applies it by a matrix-vector product below ([0-9]+) nodes",
     lambda: (_module("bearing_fem.physics.elasticity").LINE_DENSE_AUTO_CAP,
              _module("bearing_fem.physics.elasticity").LINE_FFT_APPLY_MIN)),
    # Newton and continuation (theory.md 5.2, 6.1, 6.3, 6.4)
    ("theory.md", r"largest, ([0-9.e+-]+) \(`bearing_fem\.contacts\.problem\.FB_SMOOTHING`\)",
     lambda: (_module("bearing_fem.contacts.problem").FB_SMOOTHING,)),
    ("theory.md", r"down to 2\^-([0-9]+) with the merit",
     lambda: (round(-math.log2(_default("bearing_fem.numerics.newton", "damped_newton",
                                         "min_step"))),)),
    ("theory.md", r"max\(f over the last ([0-9]+) iterates\)",
     lambda: (_default("bearing_fem.numerics.newton", "damped_newton", "memory"),)),
    ("theory.md", r"The first increment is ([0-9.]+)\.",
     lambda: (_module("bearing_fem.contacts.driver").DriverSettings().first_step,)),
    ("theory.md", r"It gives up below an increment of ([0-9.e+-]+) or after ([0-9]+) steps",
     lambda: (_default("bearing_fem.numerics.newton", "continuation", "min_increment"),
              _default("bearing_fem.numerics.newton", "continuation", "max_steps"))),
    ("theory.md", r"cap\): ([0-9]+) for lines, ([0-9]+) for a point level",
     lambda: (_module("bearing_fem.contacts.line").ATTEMPT_ITERATIONS,
              _module("bearing_fem.contacts.point").TRANSFER_DIRECT_ITERATIONS)),
    ("theory.md", r"s = ([0-9.]+) with that solution itself \(`point\.WARM_START_ALPHA`\)",
     lambda: (_module("bearing_fem.contacts.point").WARM_START_ALPHA,)),
    ("theory.md", r"u_m\(s\) = u_m ([0-9]+)\^\(1 - s\)",
     lambda: (_module("bearing_fem.contacts.line").CONTINUATION_SPEED_FACTOR,)),
    ("theory.md", r"at least ([0-9]+) nodes, `line\.COARSEST_NODES`",
     lambda: (_module("bearing_fem.contacts.line").COARSEST_NODES,)),
    ("theory.md", r"at least ([0-9]+) per direction, `point\.COARSEST_NODES`",
     lambda: (_module("bearing_fem.contacts.point").COARSEST_NODES,)),
    ("theory.md", r"Newton tolerance of ([0-9.e+-]+) \(`point\.COARSE_TOLERANCE`\)",
     lambda: (_module("bearing_fem.contacts.point").COARSE_TOLERANCE,)),
    # default line grids (theory.md 6.7, scenes.md)
    ("theory.md", r"\| ([0-9]+)/6 \(M/100\)\^([0-9.]+) per b .*?, at least ([0-9]+), "
     r"at most ([0-9]+) \|",
     lambda: (round(6 * _module("bearing_fem.contacts.line").NODES_PER_HALF_WIDTH, 9),
              _module("bearing_fem.contacts.line").DENSITY_MOES_EXPONENT, 801,
              _module("bearing_fem.contacts.line").MAX_DEFAULT_ELASTIC_NODES)),
    ("scenes.md", r"([0-9]+)/6 \(M/100\)\^([0-9.]+) nodes per b",
     lambda: (round(6 * _module("bearing_fem.contacts.line").NODES_PER_HALF_WIDTH, 9),
              _module("bearing_fem.contacts.line").DENSITY_MOES_EXPONENT)),
    ("scenes.md", r"a `local` scene at least ([0-9]+) sqrt\(max\(1, M/([0-9]+)\)\)",
     lambda: (_module("bearing_fem.contacts.line").LOCAL_NODES_PER_HALF_WIDTH,
              _module("bearing_fem.contacts.line").DENSE_MESH_MOES_M)),
    ("theory.md", r"local compliance: at least ([0-9]+) sqrt\(max\(1, M/([0-9]+)\)\) per b",
     lambda: (_module("bearing_fem.contacts.line").LOCAL_NODES_PER_HALF_WIDTH,
              _module("bearing_fem.contacts.line").DENSE_MESH_MOES_M)),
    ("scenes.md", r"([0-9]+) nodes per unit, at least 801 and at most ([0-9]+) nodes",
     lambda: (_module("bearing_fem.contacts.line").NODES_PER_RIGID_LENGTH, 20001)),
    ("scenes.md", r"a load above it \(([0-9.]+) times it,\s+`RIGID_BARUS_LOAD_MARGIN`",
     lambda: (_module("bearing_fem.contacts.line").RIGID_BARUS_LOAD_MARGIN,)),
    ("scenes.md", r"above ([0-9.]+) times it \(`RIGID_BARUS_POINT_LOAD_MARGIN`",
     lambda: (_module("bearing_fem.contacts.point").RIGID_BARUS_POINT_LOAD_MARGIN,)),
    ("theory.md", r"whose load exceeds ([0-9.]+) times its largest load",
     lambda: (_module("bearing_fem.contacts.point").RIGID_BARUS_POINT_LOAD_MARGIN,)),
    ("theory.md", r"converged pressure peaks beyond alpha p = ([0-9.]+),",
     lambda: (_module("bearing_fem.contacts.line").RIGID_BARUS_RESOLVABLE_ALPHA_P,)),
    # default point grids (point.md)
    ("point.md", r"Default rigid grid: ([0-9]+) x ([0-9]+) nodes, sinh-graded "
     r"\(x = ([0-9.]+) L sinh\(s\)",
     lambda: (_module("bearing_fem.contacts.point").RIGID_NODES,
              _module("bearing_fem.contacts.point").RIGID_NODES, 1.5)),
    ("point.md", r"above Moes M = ([0-9]+) \(`HIGH_LOAD_MOES_M`\)",
     lambda: (_module("bearing_fem.contacts.point").HIGH_LOAD_MOES_M,)),
    ("point.md", r"default ([0-9]+) x ([0-9]+) nodes on x in",
     lambda: (_module("bearing_fem.contacts.transient").ELASTIC_GAP_NODES,) * 2),
    # post-processing (theory.md 8)
    ("theory.md", r"below ([0-9]+) nm \(`post\.MOLECULAR_FILM`",
     lambda: (round(_module("bearing_fem.post").MOLECULAR_FILM * 1e9),)),
    ("theory.md", r"A quantity estimated above ([0-9]+)% is\s+named in `warnings`",
     lambda: (round(_module("bearing_fem.post").ERROR_WARNING_THRESHOLD * 100),)),
]


def _default(module: str, function: str, parameter: str):
    """The default value of ``parameter`` of ``module.function``."""
    import inspect

    return inspect.signature(getattr(_module(module), function)).parameters[parameter].default


@pytest.mark.parametrize("page, pattern, values", DOCUMENTED_CONSTANTS,
                         ids=[f"{p}:{i}" for i, (p, _, _) in enumerate(DOCUMENTED_CONSTANTS)])
def test_documented_constants_match_the_code(page, pattern, values):
    """Numbers the docs state for solver constants are the constants' values (theory.md
    described the line solver's GMRES steps as solved to 1e-10 and point.md the point
    solver's forcing as min(1e-3, ...), after both had become Eisenstat-Walker terms)."""
    text = " ".join((ROOT / "docs" / page).read_text(encoding="utf-8").split())
    m = re.search(pattern, text)
    assert m, f"{page} no longer states {pattern!r}: update the page or this table"
    found = [g for g in m.groups() if g is not None]
    expected = list(values())
    assert len(found) == len(expected), (page, pattern, found, expected)
    for text_value, code_value in zip(found, expected):
        stated = text_value if isinstance(code_value, str) else float(text_value)
        assert stated == code_value, (
            f"{page} states {text_value} where the code has {code_value!r} ({pattern!r})")


FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```", re.S | re.M)
IMPORT = re.compile(r"^\s*from (bearing_fem[\w.]*) import ([\w, ]+)$", re.M)
CALL = re.compile(r"(?<![\w.])((?:bf|bearing_fem)(?:\.\w+)+|\w+)\(")


def _code_blocks(text: str) -> list[tuple[str, str]]:
    """(language, body) of the fenced blocks and ("", body) of the 4-space indented blocks
    of a Markdown page."""
    blocks = [(tag, body) for tag, body in FENCE.findall(text)]
    current: list[str] = []
    fenced = previous_blank = False
    for line in text.splitlines():
        if line.startswith("```"):
            fenced = not fenced
        elif not fenced and line.startswith("    ") and (current or previous_blank):
            current.append(line[4:])
        elif not fenced and not line.strip() and current:
            current.append("")
        elif current:
            blocks.append(("", "\n".join(current)))
            current = []
        previous_blank = not line.strip()
    if current:
        blocks.append(("", "\n".join(current)))
    return blocks


def _callable(name: str, imported: dict):
    """The function or class a call in the docs names (``bf.x``, ``bearing_fem.m.x`` or a
    name the block imported), or None."""
    import bearing_fem as bf

    parts = name.split(".")
    if parts[0] == "bf":
        obj, parts = bf, parts[1:]
    elif parts[0] == "bearing_fem":
        for k in range(len(parts), 0, -1):
            try:
                obj, parts = importlib.import_module(".".join(parts[:k])), parts[k:]
                break
            except ModuleNotFoundError:
                continue
        else:
            return None
    elif parts[0] in imported:
        obj, parts = imported[parts[0]], parts[1:]
    else:
        return None
    for part in parts:
        if not hasattr(obj, part):
            return None
        obj = getattr(obj, part)
    return obj if callable(obj) else None


def _arguments(text: str, start: int) -> str | None:
    """The text between the bracket at ``start`` and its partner."""
    depth = 0
    for k in range(start, len(text)):
        depth += text[k] in "([{"
        depth -= text[k] in ")]}"
        if depth == 0:
            return text[start + 1:k]
    return None


def _call_problems(text: str, imported: dict) -> list[str]:
    """Keywords of calls that the function does not take, and, for a signature shown
    (``f(a, b=1, *, c=None)``), parameters it does not have, defaults that differ and
    keyword-only markers that do not hold."""
    import ast
    import inspect

    out = []
    for m in CALL.finditer(text):
        func = _callable(m.group(1), imported)
        args = _arguments(text, m.end() - 1) if func is not None else None
        if args is None:
            continue
        try:
            params = inspect.signature(func).parameters
        except (TypeError, ValueError):
            continue
        if any(p.kind is p.VAR_KEYWORD for p in params.values()):
            continue
        shown = f"{m.group(1)}({' '.join(args.split())})"
        try:
            call = ast.parse(f"f({args})", mode="eval").body
        except SyntaxError:
            call = None
        if call is not None:
            out += [f"{shown}: no parameter {kw.arg!r}" for kw in call.keywords
                    if kw.arg and kw.arg not in params]
            continue
        try:
            sig = ast.parse(f"def f({args}): pass").body[0].args
        except SyntaxError:
            continue
        positional = sig.posonlyargs + sig.args
        defaults = dict(zip([a.arg for a in sig.args][len(sig.args) - len(sig.defaults):],
                            sig.defaults))
        defaults |= {a.arg: d for a, d in zip(sig.kwonlyargs, sig.kw_defaults) if d is not None}
        keyword_only = inspect.Parameter.KEYWORD_ONLY
        for a in positional + sig.kwonlyargs:
            if a.arg not in params:
                out.append(f"{shown}: no parameter {a.arg!r}")
            elif (a in sig.kwonlyargs) != (params[a.arg].kind is keyword_only):
                out.append(f"{shown}: {a.arg!r} keyword-only in one of docs and code only")
        for a in positional + sig.kwonlyargs:
            if (a.arg in params and a.arg not in defaults
                    and params[a.arg].default is not inspect.Parameter.empty):
                out.append(f"{shown}: {a.arg!r} shown without its default "
                           f"{params[a.arg].default!r}")
        for name, node in defaults.items():
            try:
                value = ast.literal_eval(node)
            except ValueError:
                continue
            if name in params and params[name].default != value:
                out.append(f"{shown}: default {name}={value!r}, code "
                           f"{params[name].default!r}")
    return out


def test_code_in_the_docs_calls_what_exists():
    """Every ``from bearing_fem... import name`` of a code block in the docs imports, a
    fenced Python block compiles, and the calls and signatures shown in code blocks and
    code spans (``bf.x(...)``, ``bearing_fem.m.x(...)``, imported names, and the names of
    the module a heading names, e.g. "## Scalings (`bearing_fem.units`)") use parameters
    the code has, with its defaults and keyword-only markers (analytic.md showed rx,
    e_prime and piezo of point_scene_parameters_from_moes as required; they default to
    0.01 m, 2.2e11 Pa and 2e-8 1/Pa)."""
    checked, bad = 0, []
    for page in PAGES:
        text = page.read_text(encoding="utf-8")
        for tag, body in _code_blocks(text):
            if tag == "python":
                compile(body, f"{page.name} python block", "exec")
            imported = {}
            for module_name, names in IMPORT.findall(body):
                module = importlib.import_module(module_name)
                for name in (n.strip() for n in names.split(",")):
                    checked += 1
                    if hasattr(module, name):
                        imported[name] = getattr(module, name)
                    else:
                        bad.append(f"{page.name}: {module_name} has no {name}")
            problems = _call_problems(body, imported)
            checked += len(CALL.findall(body))
            bad += [f"{page.name} (code block): {p}" for p in problems]
        module = None
        for paragraph in re.split(r"\n\s*\n|\n(?=- )", text):
            head = re.search(r"^#{2,3} .*?`(bearing_fem(?:\.\w+)*)", paragraph, re.M)
            if paragraph.lstrip().startswith("#"):
                module = None
                if head:
                    try:
                        module = importlib.import_module(head.group(1))
                    except ModuleNotFoundError:
                        module = None
            names = {} if module is None else vars(module)
            for span in re.findall(r"`([^`]+)`", paragraph):
                bad += [f"{page.name} (code span): {p}" for p in _call_problems(span, names)]
    assert checked > 40, f"only {checked} imports and calls found in code blocks"
    assert not bad, "code in the docs that does not match the code:\n" + "\n".join(bad)


def test_line_map_table_is_on_the_current_default_grids():
    """The EHL map of line_contact.md states it is on the solver's own default mesh and
    one with half its spacing: each row's node counts are those the study computes now
    (`default_nodes`, 2N - 1); rows from before the default grids had N - 1 divisible
    by 4 (2943 nodes where the default is 2945) fail here until the study is rerun."""
    import sys

    sys.path.insert(0, str(ROOT / "studies"))
    try:
        import line_ehl_map
    finally:
        sys.path.remove(str(ROOT / "studies"))
    text = (ROOT / "docs" / "line_contact.md").read_text(encoding="utf-8")
    rows = re.findall(r"^\| ([0-9.]+) \| ([0-9.]+) \| [0-9.]+ \| ([0-9]+) / ([0-9]+) \|", text,
                      re.M)
    assert len(rows) >= 40, f"only {len(rows)} map rows found (table format changed?)"
    bad = []
    for m, l, n, fine in rows:
        default = line_ehl_map.default_nodes(float(m), float(l))
        if (int(n), int(fine)) != (default, 2 * default - 1):
            bad.append(f"M = {m}, L = {l}: {n} / {fine}, default now {default}")
    assert not bad, "map rows not on the current default grids:\n" + "\n".join(bad)


def _section(page: str, heading: str) -> str:
    """The text of one section of a docs page, from its heading to the next heading."""
    text = (ROOT / "docs" / page).read_text(encoding="utf-8")
    start = text.index(heading)
    end = re.search(r"^#{1,6} ", text[start + len(heading):], re.M)
    return text[start:start + len(heading) + (end.start() if end else len(text))]


def test_every_summary_key_and_result_attribute_is_documented():
    """``Result.summary()`` says docs/api.md lists every key: each key of the summaries of
    a rigid line, an elastic sliding roller with a length, a rigid and an elastic ball and
    a thermal roller is named in api.md's "Summary keys" (or, for the thermal loop's own keys, in
    coupling.md section 1), and every field of ``Result`` in api.md's attribute table
    (warnings, error_estimate, traction_model, h_outlet, gmres_iterations and the
    Poiseuille diagnostics were missing)."""
    from dataclasses import fields

    import bearing_fem as bf
    from bearing_fem.result import Result

    base = {"lubricant": {"viscosity": 0.05, "piezo": 2e-8},
            "kinematics": {"u1": 2.2, "u2": 1.8}}
    scenes = [
        {"contact": {"kind": "line", "rx": 0.01}, "model": {"elasticity": "rigid"},
         "load": {"gap": 1e-6}, "mesh": {"nodes": 201}},
        {"contact": {"kind": "line", "rx": 0.01, "length": 0.02},
         "materials": {"reduced_modulus": 2.3e11}, "load": {"force": 2e5},
         "mesh": {"nodes": 201}},
        {"contact": {"kind": "point", "rx": 0.01, "ry": 0.02},
         "model": {"elasticity": "rigid"}, "load": {"gap": 1e-6},
         "mesh": {"nodes": [33, 33]}},
        {"contact": {"kind": "point", "rx": 0.0127, "ry": 0.0127},
         "materials": {"reduced_modulus": 2.3e11}, "load": {"force": 30.0},
         "mesh": {"nodes": [65, 65]}},
        {"contact": {"kind": "line", "rx": 0.01}, "materials": {"reduced_modulus": 2.3e11},
         "load": {"force": 2e5}, "mesh": {"nodes": 201}, "model": {"thermal": "patch"},
         "thermal": {"oil_temperature": 60.0, "exponent": 3.0}},
    ]
    summary_keys = " ".join(re.findall(r"`([^`]+)`", _section("api.md", "### Summary keys")))
    thermal_keys = _section("coupling.md", "## 1. The coupling loop")
    documented = set(re.findall(r"[A-Za-z_0-9]+", summary_keys))
    bad = []
    for extra in scenes:
        result = bf.solve(bf.Scene.from_dict(base | extra))
        assert result.success, result.message
        for key in result.summary():
            if key not in documented and f"`{key}`" not in thermal_keys:
                bad.append(f"summary key {key!r} ({extra['contact']['kind']}"
                           f"{', thermal' if 'thermal' in extra else ''})")
    table = _section("api.md", "## `Result` (`bearing_fem.result`)")
    bad += [f"Result.{f.name}" for f in fields(Result) if f"`{f.name}`" not in table]
    assert not bad, "not documented in docs/api.md:\n" + "\n".join(bad)
