"""The import rules of docs/architecture.md, checked on the source (imports inside
functions included): no cycles, no private names across modules, arrows one way."""
from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parents[1] / "bearing_fem"


def _module_name(path: Path) -> str:
    parts = list(path.relative_to(PACKAGE.parent).with_suffix("").parts)
    if parts[-1] == "__init__":
        parts.pop()
    return ".".join(parts)


def _imports() -> dict[str, list[tuple[str, list[str]]]]:
    """module -> [(imported module, [names imported from it])], every import statement."""
    out: dict[str, list[tuple[str, list[str]]]] = {}
    for path in sorted(PACKAGE.rglob("*.py")):
        mod = _module_name(path)
        package = mod if path.name == "__init__.py" else mod.rpartition(".")[0]
        found = []
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                found += [(a.name, []) for a in node.names if a.name.startswith("bearing_fem")]
            elif isinstance(node, ast.ImportFrom):
                if node.level:
                    base = package.split(".")[:len(package.split(".")) - (node.level - 1)]
                    target = ".".join(base + ([node.module] if node.module else []))
                else:
                    target = node.module or ""
                if not target.startswith("bearing_fem"):
                    continue
                names = [a.name for a in node.names]
                # "from . import post" imports a module, not a name of the package
                subs = [n for n in names if (PACKAGE.parent / (target + "." + n).replace(".", "/")
                                             ).with_suffix(".py").exists()
                        or (PACKAGE.parent / (target + "." + n).replace(".", "/")).is_dir()]
                found += [(target + "." + n, []) for n in subs]
                rest = [n for n in names if n not in subs]
                if rest:
                    found.append((target, rest))
        out[mod] = found
    return out


IMPORTS = _imports()


def test_walk_sees_the_package():
    assert {"bearing_fem.contacts.driver", "bearing_fem.physics.reynolds",
            "bearing_fem.numerics.newton", "bearing_fem.cli"} <= set(IMPORTS)


def test_no_private_names_across_modules():
    bad = [f"{mod} imports {name} from {target}" for mod, found in IMPORTS.items()
           for target, names in found for name in names
           if name.startswith("_") and not name.endswith("__") and target != mod]
    assert not bad, "\n".join(bad)


def test_no_import_cycles():
    graph = {mod: {t for t, _ in found if t in IMPORTS and t != mod}
             for mod, found in IMPORTS.items()}
    # a submodule importing a name from its own (lazy or re-exporting) package __init__
    # is the package's public face, not a cycle of the code
    for mod in graph:
        graph[mod] = {t for t in graph[mod] if not mod.startswith(t + ".")}
    state: dict[str, int] = {}
    cycles = []

    def visit(node: str, stack: list[str]) -> None:
        state[node] = 1
        for nxt in sorted(graph[node]):
            if state.get(nxt) == 1:
                cycles.append(" -> ".join(stack[stack.index(nxt):] + [node, nxt])
                              if nxt in stack else f"{node} -> {nxt}")
            elif nxt not in state:
                visit(nxt, stack + [node])
        state[node] = 2

    for mod in sorted(graph):
        if mod not in state:
            visit(mod, [])
    assert not cycles, "import cycles:\n" + "\n".join(cycles)


def _layer(mod: str) -> str:
    parts = mod.split(".")
    return parts[1] if len(parts) > 1 else ""


FACES = {"cli", "io", "plot", "plot_bearing", "__main__"}


def test_arrows_run_one_way():
    """physics/numerics import no contact, bearing, sweep or face; contacts import no
    bearing, sweep or face; bearing and sweep import no face but io."""
    forbidden = {
        "physics": {"contacts", "bearing", "sweep"} | FACES,
        "numerics": {"physics", "contacts", "bearing", "sweep"} | FACES,
        "contacts": {"bearing", "sweep"} | FACES,
        "bearing": {"sweep", "cli", "plot", "plot_bearing"},
    }
    bad = [f"{mod} imports {target}" for mod, found in IMPORTS.items()
           for target, _ in found
           if _layer(target) in forbidden.get(_layer(mod), set())]
    assert not bad, "\n".join(bad)
