"""README.md cannot rot: its Python blocks run, its TOML scenes validate, its set-up
commands match what ``.ci/run`` executes, and its links point at files in the repository."""
from __future__ import annotations

import re
import runpy
import shlex
from pathlib import Path

import pytest

from bearing_fem.scene import Scene

ROOT = Path(__file__).resolve().parents[1]
README = ROOT / "README.md"
FENCE = re.compile(r"^```(\w*)[^\n]*\n(.*?)^```", re.S | re.M)


def _blocks(lang: str) -> list[str]:
    return [body for tag, body in FENCE.findall(README.read_text(encoding="utf-8"))
            if tag == lang]


PYTHON_BLOCKS = _blocks("python")


def test_readme_has_blocks():
    assert len(PYTHON_BLOCKS) >= 1 and len(_blocks("toml")) >= 1 and _blocks("sh")


@pytest.mark.parametrize("index", range(len(PYTHON_BLOCKS)))
def test_python_block_runs(index, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # blocks write output folders relative to the cwd
    if "ball_sweep.toml" in PYTHON_BLOCKS[index]:  # the sweep block: a small stand-in
        (tmp_path / "ball.toml").write_text(
            '[contact]\nkind = "line"\nrx = 0.01\n[lubricant]\nviscosity = 0.01\n'
            '[model]\nelasticity = "rigid"\n[load]\ngap = 1e-6\n[kinematics]\nu1 = 1.0\n'
            'u2 = 1.0\n[mesh]\nnodes = 101\n', encoding="utf-8")
        (tmp_path / "ball_sweep.toml").write_text(
            '[sweep]\nscene = "ball.toml"\n[axes]\n"load.gap" = [1e-6, 2e-6]\n',
            encoding="utf-8")
    script = tmp_path / f"readme_block_{index}.py"
    script.write_text(PYTHON_BLOCKS[index], encoding="utf-8")
    runpy.run_path(str(script), run_name="__main__")


def test_api_block_reports_a_solution(tmp_path, monkeypatch, capsys):
    """The first example must actually solve and write its files, not just run."""
    monkeypatch.chdir(tmp_path)
    script = tmp_path / "readme_block_0.py"
    script.write_text(PYTHON_BLOCKS[0], encoding="utf-8")
    namespace = runpy.run_path(str(script), run_name="__main__")
    assert namespace["result"].success, namespace["result"].message
    assert sorted(p.name for p in (tmp_path / "out").iterdir()) == [
        "fields.vtu", "result.h5", "summary.json"]
    assert "p_max" in capsys.readouterr().out


@pytest.mark.parametrize("index", range(len(_blocks("toml"))))
def test_toml_block_is_a_valid_scene(index):
    Scene.from_toml_string(_blocks("toml")[index], source=f"README toml block {index}")


def _setup_lines() -> list[str]:
    first = _blocks("sh")[0]
    return [line.strip() for line in first.splitlines() if line.strip()]


def test_readme_starts_with_two_setup_commands():
    text = README.read_text(encoding="utf-8")
    # the first code block of the file is the set-up block
    assert FENCE.search(text).group(2) == _blocks("sh")[0]
    lines = _setup_lines()
    assert len(lines) == 2
    assert "pip install ." in lines[0] and lines[0].endswith("bearing-fem demo")
    assert 'pip install ".[test]"' in lines[1] and "pytest" in lines[1]
    for line in lines:
        assert line.startswith("python3 -m venv .venv && . .venv/bin/activate && ")


def test_ci_runs_the_readme_commands():
    """.ci/run installs and tests exactly as the README's second line says."""
    ci = "\n".join(line for line in (ROOT / ".ci" / "run").read_text(encoding="utf-8")
                   .splitlines() if not line.lstrip().startswith("#"))
    steps = _setup_lines()[1].split(" && ")
    install, test = steps[2], steps[3]
    assert install in ci, f"{install!r} not in .ci/run"
    assert test in ci, f"{test!r} not in .ci/run"
    assert shlex.split(install)[:2] == ["pip", "install"]


def test_no_machine_paths():
    text = README.read_text(encoding="utf-8")
    for marker in ("/work/", "/tmp/", "/root/", "/home/"):
        assert marker not in text


def test_links_resolve():
    """Relative links of the README point at files in the repository."""
    text = README.read_text(encoding="utf-8")
    targets = re.findall(r"\]\(((?!https?:)[^)#]+)\)", text)
    assert targets
    for target in targets:
        assert (ROOT / target).exists(), target
