"""The docs name only what exists, and the repository stands alone.

Every dotted ``bearing_fem.a.b`` name in docs/*.md and README.md must import or resolve as
an attribute, every ``bf.name`` must be an attribute of the package, and every name listed
under a ``### `bearing_fem.module``` heading of docs/api.md must exist in that module. A
renamed or moved function then fails here instead of leaving a dead name in the docs.
"""
from __future__ import annotations

import importlib
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
