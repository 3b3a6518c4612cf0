"""The multigrid cross-check study: output parsing, the settings ladder, and its wiring.

The real multigrid program is not part of the package; a stand-in script that prints its
output format (NaN for some settings) exercises the ladder and the table.
"""
from __future__ import annotations

import math
import stat
import sys
import textwrap

import pytest

GOOD = """
 level:  1 ii=  16, jj=  16 hx=0.375000 hy=0.375000
 k= 3, resn= 4.000e-03, g= 1.000e-02, h0=-8.6e-01, wu=  10.000
 k= 3, resn= 2.000e-03, g= 5.000e-03, h0=-8.6e-01, wu=  11.000

Level      Hm       Hm(Moes)     Hc \t\tHc(Moes)   Hc(Moes)(p_x=0)

2     1.00000e-01 2.50000e+00    2.00000e-01   5.00000e+00    5.00000e+00
3     1.10000e-01 2.20000e+00    2.10000e-01   4.60000e+00    4.60100e+00

 aen( 3  2)=1.0e-03
"""


def test_parse_fmg_output_reads_the_requested_level(load_study):
    s = load_study("point_fmg_crosscheck")
    p = s.parse_fmg_output(GOOD, 3)
    assert (p["H_min"], p["H_c"]) == (2.2, 4.6), "Moes columns 3 and 5 of the level-3 row"
    assert (p["H_min_coarser"], p["H_c_coarser"]) == (2.5, 5.0), "the level-2 row"
    assert (p["residual"], p["force_residual"]) == (2e-3, 5e-3), "last relaxation of level 3"
    assert p["relaxations"] == 2
    assert s.fmg_accepted(p)
    missing = s.parse_fmg_output(GOOD, 4)
    assert math.isnan(missing["H_min"]) and not s.fmg_accepted(missing)


def test_fmg_accepted_rejects_nan_and_unbalanced_results(load_study):
    s = load_study("point_fmg_crosscheck")
    nan = GOOD.replace("2.20000e+00", "-nan").replace("4.60000e+00", "nan")
    assert not s.fmg_accepted(s.parse_fmg_output(nan, 3)), "C printf 'nan' spellings"
    # g = -2 pi/3: no pressure at all (the force balance's load term alone)
    empty = GOOD.replace("g= 5.000e-03", f"g={-2 * math.pi / 3:.3e}")
    assert not s.fmg_accepted(s.parse_fmg_output(empty, 3))
    diverged = GOOD.replace("resn= 2.000e-03", "resn= 2.615e+00")
    assert not s.fmg_accepted(s.parse_fmg_output(diverged, 3))


@pytest.fixture
def fake_fmg(tmp_path):
    """A stand-in program: NaN unless started on level 2, then GOOD's films."""
    prog = tmp_path / "fake_fmg.py"
    prog.write_text(textwrap.dedent(f"""\
        #!{sys.executable}
        import sys
        M, L, levels, start, cycles, kind = sys.stdin.read().split()
        good = {GOOD!r}
        if start != "2":
            good = good.replace("2.20000e+00", "-nan").replace("4.60000e+00", "-nan")
        print(good.replace("k= 3", "k= " + levels).replace("\\n3     ", "\\n" + levels + "     "))
        """))
    prog.chmod(prog.stat().st_mode | stat.S_IXUSR)
    return prog


def test_run_fmg_walks_the_ladder(load_study, fake_fmg):
    s = load_study("point_fmg_crosscheck")
    out = s.run_fmg(fake_fmg, 100.0, 10.0, levels=3)
    first = next(i for i, (start, _, _) in enumerate(s.FMG_LADDER) if start == 2)
    assert out["failed_settings"] == first, "the settings before the first start level 2"
    assert out["result"]["start"] == 2 and out["result"]["H_min"] == 2.2
    assert len(out["tried"]) == first + 1


def test_main_compares_films_in_moes_units(load_study, fake_fmg, tmp_path):
    s = load_study("point_fmg_crosscheck")
    out = s.main(tmp_path / "out", fmg=fake_fmg, cases=[(100.0, 10.0)], levels=(3,))
    row = out["cases"][0]
    assert row["nodes"] == 65, "3 multigrid levels = 64 x 64 intervals = 65^2 nodes here"
    assert row["status"] == "converged"
    assert row["H_min_vs_fmg"] == pytest.approx(100 * (row["H_min"] / 2.2 - 1), rel=1e-12)
    # H_c here in Moes units must be the NVM-sized film (about 4.6 at M = 100, L = 10)
    assert 4.0 < row["H_c"] < 5.5, f"H_c = {row['H_c']} is not a Moes-scaled film"
    assert (tmp_path / "out" / "point_fmg_crosscheck.md").is_file()


def test_main_names_a_missing_program(load_study, tmp_path):
    s = load_study("point_fmg_crosscheck")
    with pytest.raises(ValueError, match="fmg"):
        s.main(tmp_path, fmg=tmp_path / "nowhere")
