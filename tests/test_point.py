"""Point/elliptical contacts (bearing_fem.contacts.point): Kapitsa oracles, convergence, status.

The rigid oracles (docs/theory.md section 14.1) are imposed as Dirichlet data on the finite domain,
so only the discretisation error is measured.
"""
from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
import scipy.sparse as sp

import bearing_fem as bf
from bearing_fem import analytic as an
from bearing_fem.contacts.point import solve_point
from bearing_fem.contacts.point_grid import PointGrid
from bearing_fem.scene import (Contact, Kinematics, Load, Lubricant, Materials, MeshSpec,
                               Model, Scene, SolverSpec)

ETA0 = 0.01      # Pa s
U_M = 1.0        # m/s
H0 = 1e-7        # m


def rigid_scene(rx: float, ry: float, *, piezo: float = 0.0, cavitation: str = "none",
                nodes=None, x_range=None, y_range=None) -> Scene:
    return Scene(contact=Contact(kind="point", rx=rx, ry=ry),
                 lubricant=Lubricant(viscosity=ETA0, piezo=piezo),
                 kinematics=Kinematics(u1=U_M, u2=U_M), load=Load(gap=H0),
                 model=Model(elasticity="rigid", cavitation=cavitation),
                 mesh=MeshSpec(nodes=nodes, x_range=x_range, y_range=y_range))


def exact_fn(rx, ry, dh0dt, piezo=0.0):
    a, b = 1 / (2 * rx), 1 / (2 * ry)
    return lambda x, y: an.kapitsa_point_pressure(x, y, H0, a, b, ETA0, U_M, dh0dt, piezo)


def q_max(rx, ry, dh0dt):
    return float(an.kapitsa_point_max_reduced(H0, 1 / (2 * rx), 1 / (2 * ry), ETA0, U_M, dh0dt))


CASES = [  # (rx, ry, dh0/dt): wedge, squeeze, both; circular and elliptical
    (0.01, 0.01, 0.0), (0.01, 0.01, -2e-4), (0.01, 0.04, 0.0), (0.01, 0.04, -1e-4),
    (0.02, 0.005, -1e-4),
]


@pytest.mark.parametrize("rx, ry, dh0dt", CASES)
@pytest.mark.parametrize("ratio", [0.0, 0.9])
def test_kapitsa_peak_default_mesh(rx, ry, dh0dt, ratio):
    qm = q_max(rx, ry, dh0dt)
    piezo = ratio / qm
    res = solve_point(rigid_scene(rx, ry, piezo=piezo), boundary_pressure=exact_fn(
        rx, ry, dh0dt, piezo), squeeze_velocity=dh0dt)
    assert res.status == "linear", res.message
    assert res.pressure.shape == (res.y.size, res.x.size)
    p_exact = float(an.barus_from_reduced(qm, piezo))
    np.testing.assert_allclose(res.quantities["p_max"], p_exact, rtol=5e-3,
                               err_msg="p_max within 0.5% of Kapitsa on the default graded "
                                       "161^2 mesh (design target; the Barus case at "
                                       "alpha q_max = 0.9 amplifies q errors 10x)")
    assert np.all(np.isfinite(res.pressure))
    # the rigid film is the prescribed gap plus the geometry
    assert res.quantities["h_central"] == pytest.approx(H0, rel=1e-12)
    assert res.quantities["h_min"] >= H0 * (1 - 1e-12)


def _l2_error(res, exact) -> float:
    grid = PointGrid.tensor(res.x, res.y)
    ops = grid.ops
    xq, yq = ops.points
    err = ops.value @ res.pressure.ravel() - exact(xq, yq)
    return math.sqrt(ops.integrate(err**2)) / math.sqrt(ops.integrate(exact(xq, yq) ** 2))


@pytest.mark.parametrize("rx, ry, dh0dt, ratio", [(0.01, 0.01, -1e-4, 0.0),
                                                  (0.01, 0.04, 0.0, 0.5)])
def test_kapitsa_l2_convergence_order(rx, ry, dh0dt, ratio):
    piezo = ratio / q_max(rx, ry, dh0dt)
    exact = exact_fn(rx, ry, dh0dt, piezo)
    hs, errs = [], []
    for n in (17, 33, 65):
        res = solve_point(rigid_scene(rx, ry, piezo=piezo, nodes=(n, n), x_range=(-3.0, 3.0),
                                      y_range=(-3.0, 3.0)),
                          boundary_pressure=exact, squeeze_velocity=dh0dt)
        assert res.success, res.message
        hs.append(res.x[1] - res.x[0])
        errs.append(_l2_error(res, exact))
    order = np.polyfit(np.log(hs), np.log(errs), 1)[0]
    assert order >= 1.8, (f"observed L2 order {order:.2f} < 1.8 (bilinear elements: 2 in "
                          f"theory); errors {errs} at spacings {hs}")


def test_beyond_existence_is_no_solution():
    rx = ry = 0.01
    piezo = 1.2 / q_max(rx, ry, 0.0)
    res = solve_point(rigid_scene(rx, ry, piezo=piezo, nodes=(61, 61)))
    assert res.status == "no_solution" and not res.success
    assert "alpha*q_max" in res.message
    assert np.all(np.isfinite(res.pressure)), "fields hold q, never NaN"


def test_reynolds_cavitation_rigid():
    rx, ry = 0.01, 0.02
    res = solve_point(rigid_scene(rx, ry, cavitation="reynolds", nodes=(61, 61)))
    assert res.status == "linear", res.message
    assert np.min(res.pressure) >= 0.0, "Reynolds cavitation: p >= 0"
    assert res.quantities["load"] > 0.0
    # the cavitated (p = 0) zone lies downstream of the centre
    p = res.pressure
    j0 = int(np.argmin(np.abs(res.y)))
    zero_x = res.x[(p[j0] <= 0.0)]
    assert np.any(zero_x > 0.0)
    assert np.isfinite(res.quantities["friction_force"])
    assert res.quantities["heat_power"] > 0.0


def test_bad_input():
    scene = rigid_scene(0.01, 0.01, nodes=(21, 21))
    with pytest.raises(ValueError, match="squeeze_velocity"):
        solve_point(scene, squeeze_velocity=float("nan"))
    with pytest.raises(ValueError, match="boundary_pressure"):
        solve_point(scene, boundary_pressure=np.zeros(7))


def test_squeeze_series_matches_kapitsa(tmp_path):
    from bearing_fem.contacts.series import solve_squeeze_series

    rx, ry = 0.01, 0.02
    eps = 0.3
    scene = rigid_scene(rx, ry, nodes=(121, 121))
    omega = 2.0 * U_M / math.sqrt(2 * rx * H0)  # squeeze comparable to the wedge
    series = solve_squeeze_series(scene, eps=eps, omega=omega, n_steps=8)
    assert all(s == "linear" for s in series.statuses)
    a, b = 1 / (2 * rx), 1 / (2 * ry)
    for g, rate, pm in zip(series.gap, series.squeeze_velocity, series.p_max):
        exact = float(an.kapitsa_point_max_reduced(g, a, b, ETA0, U_M, rate))
        np.testing.assert_allclose(pm, exact, rtol=1e-2,
                                   err_msg="each step within 1% of Kapitsa (design target; "
                                           "zero boundary data on +-30 contact lengths "
                                           "truncates the 1/r^3 far field)")
    np.testing.assert_allclose(series.gap, H0 * (1 + eps * np.cos(omega * series.times)))
    paths = {k: str(v) for k, v in bf.io.export_series(series, tmp_path / "series").items()}
    import meshio

    assert "DataSet" in open(paths["pvd"]).read()
    first = meshio.read(tmp_path / "series" / "squeeze_0000.vtu")
    np.testing.assert_allclose(first.point_data["pressure_Pa"],
                               series.results[0].pressure.ravel())
    with meshio.xdmf.TimeSeriesReader(paths["xdmf"]) as reader:
        reader.read_points_cells()
        t, pdata, _ = reader.read_data(3)
    np.testing.assert_allclose(t, series.times[3])
    np.testing.assert_allclose(pdata["pressure_Pa"], series.results[3].pressure.ravel())


# ---------------------------------------------------------------------------------------
# elastic (half-space) point EHL
# ---------------------------------------------------------------------------------------
def _moes_scene(M, L, nodes, ry_over_rx=1.0, max_iterations=30):
    from bearing_fem.units import point_scene_parameters_from_moes

    d = point_scene_parameters_from_moes(M, L, rx=0.01, ry=0.01 * ry_over_rx)
    u = d["mean_speed"]
    return Scene(contact=Contact(kind="point", rx=d["rx"], ry=d["ry"]),
                 materials=Materials(reduced_modulus=d["e_prime"]),
                 lubricant=Lubricant(viscosity=d["viscosity"], piezo=d["piezo"]),
                 kinematics=Kinematics(u1=u, u2=u), load=Load(force=d["force"]),
                 mesh=MeshSpec(nodes=(nodes, nodes)),
                 solver=SolverSpec(max_iterations=max_iterations))


@pytest.mark.parametrize("M, L, ry_over_rx", [(100, 10, 1.0), (20, 10, 1.0), (50, 5, 3.0)])
def test_elastic_point_converges_near_nvm(M, L, ry_over_rx):
    from bearing_fem.formulas import point_central_film_nvm

    scene = _moes_scene(M, L, 65, ry_over_rx)
    res = solve_point(scene)
    assert res.status == "converged", res.message
    assert res.newton_iterations < 40, f"cost cap: {res.newton_iterations} Newton iterations"
    c, lub = scene.contact, scene.lubricant
    hc = point_central_film_nvm(scene.load.force, c.rx, c.ry, scene.e_prime, lub.viscosity,
                                scene.kinematics.mean_speed, lub.piezo)
    np.testing.assert_allclose(res.quantities["h_central"], hc, rtol=0.10,
                               err_msg="central film within 10% of Nijenbanning-Venner-Moes "
                                       "(design target; 65^2 grid, first-order upwind "
                                       "wedge in the Hertz zone, NVM itself is a fit)")
    np.testing.assert_allclose(res.quantities["load"], scene.load.force, rtol=1e-6,
                               err_msg="load row satisfied to the Newton tolerance")
    assert np.min(res.pressure) >= 0.0
    assert np.all(np.isfinite(res.film)) and res.quantities["h_min"] > 0.0
    assert res.quantities["h_min"] < res.quantities["h_central"]
    assert res.pressure.shape == (res.y.size, res.x.size)


def test_high_piezoviscosity_converges_directly_on_two_grids():
    # alpha p_h = 33.8: without the initial Newton shift the direct attempts stalled on
    # 65^2 and again on 129^2 (alpha continuation from scratch: 157 iterations in all)
    scene = _moes_scene(100, 20, 129)
    res = solve_point(scene)
    assert res.status == "converged", res.message
    assert all(s == 1.0 for s, _, _ in res.continuation), (
        f"no alpha continuation expected: {res.continuation}")
    assert res.newton_iterations < 50, f"cost cap: {res.newton_iterations} Newton iterations"
    coarse, fine = res.continuation
    assert "65x65" in coarse[1] and "129x129" in fine[1]


def test_fine_level_never_restarts_alpha_continuation_from_scratch():
    # alpha p_h = 19.8, (M, L) = (20, 20): the direct attempt on 129^2 from the 65^2
    # solution may cycle at the outlet spike; the fallback continues in alpha from that
    # interpolated solution (s = 0.8 -> 1), not from the Hertzian start at s = 0
    res = solve_point(_moes_scene(20, 20, 129))
    assert res.status == "converged", res.message
    fine = [(s, i) for s, st, i in res.continuation if "129x129" in st]
    assert all(s > 0.0 for s, _ in fine), f"continuation from scratch: {res.continuation}"
    assert res.newton_iterations < 60, f"cost cap: {res.newton_iterations} Newton iterations"


@pytest.mark.parametrize("ry_over_rx", [1.0, 3.0])
def test_half_grid_solve_equals_whole_grid_solve(monkeypatch, ry_over_rx):
    # The y-symmetric scene is solved on its half y >= 0 and mirrored; the same scene on
    # the whole grid must give the same fields, and the reported residual is the whole
    # grid's. (The Newton paths differ slightly: the incomplete single-precision
    # preconditioner is ordered differently on the two grids and GMRES stops early.)
    import bearing_fem.contacts.point as pt

    scene = _moes_scene(100, 10, 65, ry_over_rx)
    half = solve_point(scene)
    monkeypatch.setattr(pt, "Y_SYMMETRY", False)
    whole = solve_point(scene)
    assert half.status == whole.status == "converged", half.message
    assert "by symmetry" in half.message and "by symmetry" not in whole.message
    assert abs(half.newton_iterations - whole.newton_iterations) <= 3, (half.continuation,
                                                                        whole.continuation)
    assert half.pressure.shape == whole.pressure.shape == (65, 65)
    np.testing.assert_allclose(half.pressure, whole.pressure, rtol=0,
                               atol=1e-7 * whole.quantities["p_max"],
                               err_msg="same discrete equations: fields agree to the Newton "
                                       "tolerance (1e-8 scaled), not to the discretisation")
    np.testing.assert_array_equal(half.pressure, half.pressure[::-1],
                                  err_msg="the mirrored result is exactly even in y")
    for key in ("h_central", "h_min", "p_max", "load", "friction_force"):
        np.testing.assert_allclose(half.quantities[key], whole.quantities[key], rtol=1e-7,
                                   err_msg=f"{key}: same solution to the Newton tolerance")
    residual = float(half.message.split("residual ")[1].split()[0])
    assert residual <= scene.solver.tolerance, half.message


def test_half_grid_needs_a_symmetric_scene():
    import bearing_fem.contacts.point as pt

    scene = _moes_scene(100, 10, 65)
    assert pt.PointModel(scene).symmetric
    assert not pt.PointModel(scene, lambda x, y: 0.0 * x).symmetric, "Dirichlet data given"
    even = dataclasses.replace(scene, mesh=MeshSpec(nodes=(65, 64)))
    assert not pt.PointModel(even).symmetric, "no node row at y = 0"
    shifted = dataclasses.replace(scene, mesh=MeshSpec(nodes=(65, 65), y_range=(-3.0, 2.5)))
    assert not pt.PointModel(shifted).symmetric, "asymmetric range"
    with pytest.raises(ValueError, match="y_range symmetric"):
        pt.point_setup(shifted, symmetric=True)


def test_elastic_squeeze_thickens_film_at_fixed_load():
    # An approaching surface (dh0/dt < 0) builds squeeze pressure that carries part of
    # the load, so at a fixed load the wedge needs less pressure: the film is thicker.
    from bearing_fem.formulas import point_central_film_nvm
    from bearing_fem.units import hertz_point

    scene = _moes_scene(100, 5, 65)
    c, lub, u = scene.contact, scene.lubricant, scene.kinematics.mean_speed
    hc = point_central_film_nvm(scene.load.force, c.rx, c.ry, scene.e_prime, lub.viscosity,
                                u, lub.piezo)
    a = hertz_point(scene.load.force, c.rx, c.ry, scene.e_prime).a_x
    steady = solve_point(scene)
    squeezed = solve_point(scene, squeeze_velocity=-0.2 * u * hc / a)
    assert steady.status == squeezed.status == "converged", squeezed.message
    assert squeezed.quantities["h_central"] > steady.quantities["h_central"]


@pytest.mark.slow
def test_point_ehl_map_study(tmp_path, load_study):
    mod = load_study("point_ehl_map")
    out = mod.main(tmp_path, quick=False, nodes=65, plot=False)
    solved = [r for r in out["cases"] if r["status"] != "skipped"]
    assert all(r["status"] == "converged" for r in solved), [r["message"] for r in solved]
    assert out["max_abs_hc_deviation"] < 0.15, "65^2: within 15% of NVM over the map"


def test_point_hard_cases_study_quick(tmp_path, load_study):
    # the three cases a classic multigrid code could not solve untuned
    out = load_study("point_hard_cases").main(tmp_path, quick=True)
    assert len(out["cases"]) == 3
    for c in out["cases"]:
        assert c["converged"], [r["status"] for r in c["runs"]]
        assert abs(c["h_central_vs_nvm"]) < 0.10, (
            f"M={c['M']:g}, L={c['L']:g}: 129^2 h_c within 10% of NVM (measured +3..+6%)")
    assert (tmp_path / "point_hard_cases.md").read_text().count("converged") == 6


def test_hamrock_dowson_study_density_option(tmp_path, load_study):
    mod = load_study("point_hamrock_dowson")
    inc = mod.main(tmp_path / "inc", nodes=65, ratios=(1.0, 2.0))["rows"]
    comp = mod.main(tmp_path / "dh", nodes=65, ratios=(1.0,),
                    density="dowson-higginson")["rows"]
    assert [r["status"] for r in inc + comp] == ["converged"] * 3
    assert comp[0]["h_central"] < 0.95 * inc[0]["h_central"], (
        "Dowson-Higginson compressibility lowers the central film at M = 100, L = 10 "
        "(measured -14% on 65^2)")
    assert 0.0 < comp[0]["h_min_over_h_c"] < 1.0
    assert "dowson-higginson" in (tmp_path / "dh" / "point_hamrock_dowson.md").read_text()


def test_hamrock_dowson_study_domain_scale(tmp_path, load_study):
    mod = load_study("point_hamrock_dowson")
    base = mod.main(tmp_path / "base", nodes=65, ratios=(1.0,))["rows"][0]
    big = mod.main(tmp_path / "big", nodes=65, ratios=(1.0,), domain_scale=1.5)["rows"][0]
    assert base["status"] == big["status"] == "converged"
    assert base["x_range"] is None and big["nodes"] == 97
    # default domain: outlet 1.5 a_x, inlet max(4.5, 8 sqrt(2 rx h_c)/a_x), sides half that
    assert big["x_range"][1] == pytest.approx(1.5 * 1.5) and big["x_range"][0] <= 1.5 * -4.5
    inlet = -big["x_range"][0] / 1.5
    assert big["y_range"] == pytest.approx([-1.5 * max(3.0, inlet / 2), 1.5 * max(3.0, inlet / 2)])
    np.testing.assert_allclose(big["h_min"], base["h_min"], rtol=0.02,
                               err_msg="same spacing, 1.5x domain: the films do not depend on "
                                       "where the domain ends (measured 0.4 points at most on "
                                       "257^2 spacing)")
    assert "default domain x 1.5 (97 x 97 nodes" in (
        tmp_path / "big" / "point_hamrock_dowson.md").read_text()
    with pytest.raises(ValueError, match="odd integer"):
        mod.main(tmp_path / "bad", nodes=65, ratios=(1.0,), domain_scale=1.3)


def test_point_benchmark_quick_reports_error_against_time(tmp_path, load_study):
    out = load_study("point_benchmark").main(tmp_path, quick=True, whole=True)
    rows = out["rows"]
    assert [r["nodes"] for r in rows] == [65, 129, 257]
    assert all(r["status"] == "converged" for r in rows)
    errs = [r["h_central_error_vs_finest"] for r in rows]
    assert errs[-1] == 0.0 and errs[0] > errs[1] > 0.0, (
        f"h_c error against the finest grid falls with refinement: {errs}")
    assert np.isfinite(out["growth_exponent"])
    assert [r["grid_solved"] for r in rows] == ["half"] * 3
    whole = out["rows_whole_grid"]
    assert [r["grid_solved"] for r in whole] == ["whole"] * 3
    for h, w in zip(rows, whole):
        assert w["unknowns_solved"] == h["unknowns"] > h["unknowns_solved"]
        np.testing.assert_allclose(h["h_central_m"], w["h_central_m"], rtol=1e-6,
                                   err_msg="half and whole grid solve the same equations "
                                           "(Newton tolerance 1e-8 scaled)")
    assert "h_c err" in (tmp_path / "point_benchmark.txt").read_text()
    for r in rows + whole:  # every solve in its own process reports its own peak
        assert r["peak_rss_mb"] > r["import_rss_mb"] > 0.0
        assert r["newton_iterations_finest"] >= 1 and r["time_per_iteration_s"] > 0.0
    assert rows[-1]["peak_rss_mb"] > rows[0]["peak_rss_mb"], "257^2 needs more than 65^2"
    for r in rows:  # every attempt of every level is counted once
        assert sum(r["level_iterations"]) == r["newton_iterations_total"], r["levels"]
    # quick (no 513^2, no multigrid program): the 257^2 time and the growth exponent
    judged = {t["target"].split(" ")[0] for t in out["targets"]}
    assert judged == {"257^2", "time"}, out["targets"]
    assert "targets" in (tmp_path / "point_benchmark.txt").read_text()


def test_point_map_hamrock_groups(load_study):
    text = load_study("point_ehl_map").hamrock_groups()
    rows = [line for line in text.splitlines() if line.startswith("| ") and "U" not in line]
    assert len(rows) == 13, "the 13 map cases with alpha p_h <= 40"
    assert "2.4 decades" in text and "2.5 decades" in text, (
        "U ~ (L/G)^4 spans 4^4 = 256x for L = 5..20 at fixed G; W spans 320x over the 13 "
        "cases (M = 20..500)")


def test_bearing209_study_quick(tmp_path, load_study):
    mod = load_study("bearing209")
    out = mod.main(tmp_path, quick=True)
    assert out["max_rel_diff_isoviscous_vs_kapitsa"] < 0.02, (
        "FE isoviscous maxima within 2% of Kapitsa (quick 81^2 graded mesh, zero far-field "
        "data at +-30 contact lengths)")
    for row in out["cases"]:
        assert row["solution_exists"] == (row["alpha_q_max"] < 1.0)
        assert (row["p_max_Pa"] is None) != row["solution_exists"]
    assert (tmp_path / "bearing209.json").is_file()


# ---------------------------------------------------------------------------------------
# solver internals: fast assembly, preconditioner ordering, flux derivatives
# ---------------------------------------------------------------------------------------
@pytest.mark.parametrize("kind", ["quad", "line-p2", "tri"])
def test_quadrature_operators_equal_coo_assembly(kind):
    # the maps are built directly in CSR (sorted element nodes per row); the plain COO
    # assembly of the same basis values must give the same matrices entry for entry
    from skfem import (CellBasis, ElementLineP2, ElementQuad1, ElementTriP1, MeshLine,
                       MeshQuad, MeshTri)

    from bearing_fem.numerics.fe import quadrature_operators

    basis = {"quad": lambda: CellBasis(MeshQuad.init_tensor(np.linspace(0, 1, 7),
                                                            np.linspace(0, 2, 5)),
                                       ElementQuad1()),
             "line-p2": lambda: CellBasis(MeshLine(np.linspace(0, 1, 11)), ElementLineP2()),
             "tri": lambda: CellBasis(MeshTri().refined(2), ElementTriP1())}[kind]()
    ops = quadrature_operators(basis)
    nel, nq = basis.mesh.nelements, basis.dx.shape[1]
    dofs = basis.element_dofs
    rows = np.tile(np.arange(nel * nq), dofs.shape[0])
    cols = np.concatenate([np.repeat(d, nq) for d in dofs])

    def coo(fields):
        return sp.csr_matrix((np.concatenate([np.asarray(f).ravel() for f in fields]),
                              (rows, cols)), shape=(nel * nq, basis.N))

    phis = [basis.basis[k][0] for k in range(dofs.shape[0])]
    refs = [coo(phis)] + [coo([phi.grad[d] for phi in phis])
                          for d in range(basis.mesh.dim())]
    for got, ref in zip((ops.value,) + tuple(ops.grad), refs):
        ref.sort_indices()
        assert got.has_sorted_indices
        np.testing.assert_array_equal(got.indptr, ref.indptr)
        np.testing.assert_array_equal(got.indices, ref.indices)
        np.testing.assert_array_equal(got.data, ref.data,
                                      err_msg="same values, no summation: bitwise equal")


def test_element_assembler_matches_sparse_products():
    # graded in y, uniform in x: the element-wise sum must equal the sparse-product form
    grid = PointGrid.tensor(np.linspace(-1e-3, 2e-3, 9), 1e-3 * np.sinh(np.linspace(-1, 1, 12)))
    ops = grid.ops
    rng = np.random.default_rng(3)
    nq = ops.weights.size
    terms = [(d, rng.standard_normal(nq), (rng.standard_normal(nq), rng.standard_normal(nq)))
             for d in (0, 1)]
    ref = (ops.flux_jacobian(*terms[0]) + ops.flux_jacobian(*terms[1])).toarray()
    fast = ops.assembler.flux_jacobian_sum(terms)
    np.testing.assert_allclose(fast.toarray(), ref, rtol=0, atol=1e-13 * np.abs(ref).max(),
                               err_msg="same forms, only the summation order differs")
    np.testing.assert_allclose(ops.assembler.pattern_data(sp.csr_matrix(ref)), fast.data,
                               rtol=0, atol=1e-13 * np.abs(ref).max(),
                               err_msg="pattern_data recovers the values on the pattern")
    s = rng.standard_normal(grid.size)
    scaled = ops.assembler.flux_jacobian_sum([terms[0] + (s,), terms[1]]).toarray()
    ref_scaled = (ops.flux_jacobian(*terms[0]) @ sp.diags(s) + ops.flux_jacobian(*terms[1]))
    np.testing.assert_allclose(scaled, ref_scaled.toarray(), rtol=0,
                               atol=1e-13 * np.abs(ref).max() * np.abs(s).max(),
                               err_msg="optional column scaling of one term")
    wider = np.zeros_like(ref)
    wider[0, -1] = 1.0  # nodes that share no element
    assert ops.assembler.pattern_data(sp.csr_matrix(wider)) is None


@pytest.mark.parametrize("nx, ny", [(1, 1), (7, 5), (30, 17)])
def test_nested_dissection_is_a_separator_order(nx, ny):
    from bearing_fem.contacts.point_grid import nested_dissection

    perm = nested_dissection(nx, ny, leaf=2)
    assert np.array_equal(np.sort(perm), np.arange(nx * ny))


def test_preconditioner_fast_path_equals_sparse_products(monkeypatch):
    # the gathered, dissected LU solves the same matrix as the sparse-product fallback
    scene = _moes_scene(100, 10, 17)
    import bearing_fem.contacts.point as bp

    monkeypatch.setattr(bp, "PRECONDITIONER_SINGLE", False)
    monkeypatch.setattr(bp, "PRECONDITIONER_DROP_TOL", 0.0)
    model = bp.PointModel(scene)
    level = model.level(model.fine_nodes, half=False)
    prob = model.problem(level)
    z = model.initial_guess(level, prob)
    prob.prepare(z)
    a_p, a_h, _, row_factor, da = prob._blocks(z)
    scale = row_factor * prob.p_ref
    diag = da + 0.01
    fast = prob._preconditioner_lu(a_p, a_h, scale, diag)
    slow = prob._preconditioner_lu_general(a_p, a_h, scale, diag)
    r = np.random.default_rng(0).standard_normal(prob.free.size)
    np.testing.assert_allclose(fast(r), slow(r), rtol=1e-9, atol=1e-12,
                               err_msg="two orderings of one sparse LU: rounding only")
    monkeypatch.setattr(bp, "PRECONDITIONER_SINGLE", True)
    single = prob._preconditioner_lu(a_p, a_h, scale, diag)
    ref = slow(r)
    assert single(r).dtype == np.float64
    np.testing.assert_allclose(single(r), ref, rtol=0, atol=1e-4 * np.abs(ref).max(),
                               err_msg="the single-precision factors solve the same matrix "
                               "to float32 rounding times its modest condition number")
    monkeypatch.setattr(bp, "PRECONDITIONER_DROP_TOL", 1e-3)
    incomplete = prob._preconditioner_lu(a_p, a_h, scale, diag)
    err = np.linalg.norm(incomplete(r) - ref) / np.linalg.norm(ref)
    print("incomplete factors: relative error", err)
    assert err < 0.05, ("incomplete factors (drop 1e-3) approximate the solve to a few "
                        f"percent (a preconditioner), got {err:.3g}")


def _flux_inputs(seed: int, n: int = 500):
    """Random quadrature-point states spanning the EHL range: p [Pa] (slightly negative to
    2 GPa), h [m], grad p [Pa/m], grad h [-]."""
    rng = np.random.default_rng(seed)
    return (rng.uniform(-1e7, 2e9, n), rng.uniform(5e-8, 1e-6, n),
            (1e12 * rng.standard_normal(n), 1e12 * rng.standard_normal(n)),
            (1e-3 * rng.standard_normal(n), 1e-3 * rng.standard_normal(n)), rng)


def test_upwind_flux_derivatives_match_complex_step():
    from dataclasses import replace

    import bearing_fem.contacts.point as bp
    from bearing_fem.physics.reynolds import FluxModel

    scene = _moes_scene(100, 10, 17)
    setup = bp.point_setup(scene)
    p, h, gp, gh, _ = _flux_inputs(1)
    dx = np.full(p.size, 1e-5)
    for law in ({}, {"density": "dowson-higginson"}, {"viscosity_law": "roelands"}):
        flux = bp.flux_model(replace(scene, lubricant=replace(scene.lubricant, **law)), setup)
        fast = flux.flux_and_derivatives(p, h, gp, gh, dx)
        ref = FluxModel.flux_and_derivatives(flux, p, h, gp, gh, dx)  # complex step for all
        for k in (0, 1):
            for a, b in zip(fast[k], ref[k]):
                np.testing.assert_allclose(a, b, rtol=1e-12, atol=0, err_msg=f"{law} part {k}")
        for a, b in zip(fast[2], ref[2]):
            np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-13 * np.abs(b).max(),
                                       err_msg=f"{law}: analytic dF/dh = complex step, to "
                                               f"rounding of its terms (they cancel near 0)")
        for k in (3, 4):
            for da, db in zip(fast[k], ref[k]):
                for a, b in zip(da, db):
                    np.testing.assert_allclose(a, b, rtol=1e-12, atol=1e-12 * np.abs(b).max(),
                                               err_msg=f"{law}: the flux is affine in the "
                                                       f"gradients (analytic = complex step)")


def test_reduced_flux_derivatives_match_complex_step():
    # the reduced-pressure flux used by elastic point contacts: d/dp (complex step inside)
    # and the analytic d/dh against a complex step of the flux at fixed gradients
    import bearing_fem.contacts.point as bp
    from bearing_fem.physics.reynolds import _STEP

    from dataclasses import replace

    scene = _moes_scene(100, 10, 17)
    setup = bp.point_setup(scene)
    p, h, gp, gh, rng = _flux_inputs(2)
    n = p.size
    gq = (1e10 * rng.standard_normal(n), 1e10 * rng.standard_normal(n))
    dx = np.logspace(-9, -4, n)  # Pe from the series range to the saturated one
    # the analytic d/dp differentiates the density, its slope and the viscosity by the
    # chain rule: every law, compressible included (the Peclet number follows eta only)
    for law in ({}, {"density": "dowson-higginson"}, {"viscosity_law": "roelands"}):
        flux = bp.flux_model(replace(scene, lubricant=replace(scene.lubricant, **law)),
                             setup)
        if not law:
            assert flux.reduced_alpha and flux.upwind_compliance > 0.0, "Peclet fade-out"
        base, d_p, d_h = flux.flux_and_derivatives_reduced(p, h, gp, gh, dx, gq)[:3]
        for which, fast in (("p", d_p), ("h", d_h)):
            v = p if which == "p" else h
            step = _STEP * np.abs(v).max()
            args = (p + 1j * step, h) if which == "p" else (p, h + 1j * step)
            ref = [np.imag(f) / step for f in flux.flux(*args, gp, gh, dx, gq)]
            for a, b in zip(fast, ref):
                np.testing.assert_allclose(a, b, rtol=1e-11, atol=1e-13 * np.abs(b).max(),
                                           err_msg=f"{law} d/d{which}: analytic vs complex "
                                                   f"step of the whole flux, to rounding "
                                                   f"(compressible: terms that cancel to "
                                                   f"8e-12 relative)")
        for a, b in zip(base, flux.flux(p, h, gp, gh, dx, gq)):
            np.testing.assert_array_equal(a, b, err_msg="same flux as flux()")


def test_reduced_flux_derivative_is_finite_where_barus_viscosity_overflows():
    # alpha p > ~710 (a line at M = 1e4, L = 10.7 reaches it in the outlet spike): eta is
    # inf there, Pe infinite and the upwind factor saturated, so d/dp of the upwinding
    # term is 0; the analytic derivative once gave inf/inf = NaN there, a NaN Jacobian
    # and a stalled solve
    import bearing_fem.contacts.point as bp

    scene = _moes_scene(100, 10, 17)
    setup = bp.point_setup(scene)
    flux = bp.flux_model(scene, setup)
    p, h, gp, gh, rng = _flux_inputs(2)
    alpha = scene.lubricant.piezo
    p = p.copy()
    p[: p.size // 2] = 800.0 / alpha  # alpha p = 800: exp overflows
    n = p.size
    gq = (1e10 * rng.standard_normal(n), 1e10 * rng.standard_normal(n))
    dx = np.logspace(-9, -4, n)
    with np.errstate(all="ignore"):  # inf viscosity: the solver's own errstate, as in a solve
        d_p = flux.flux_and_derivatives_reduced(p, h, gp, gh, dx, gq)[1]
    for comp in d_p:
        assert np.all(np.isfinite(comp)), "dF/dp finite where the viscosity overflows"


def test_reduced_poiseuille_newton_direction_is_exact(monkeypatch):
    # the Jacobian (element assembly, column scaling by dq/dp, FFT compliance) against
    # central differences of the residual, GMRES solved to 1e-9 (no inexact forcing)
    import bearing_fem.contacts.point as bp

    monkeypatch.setattr(bp, "GMRES_FORCING_MAX", 0.0)
    scene = _moes_scene(100, 10, 33)
    model = bp.PointModel(scene)
    level = model.level(model.fine_nodes, half=False)
    prob = model.problem(level)
    assert prob.flux.reduced_alpha == scene.lubricant.piezo
    z = model.initial_guess(level, prob)
    prob.prepare(z)
    f = prob.residual(z)
    dz = prob.newton_step(z)
    t = 1e-5
    jdz = (prob.residual(z + t * dz) - prob.residual(z - t * dz)) / (2 * t)
    np.testing.assert_allclose(jdz, -f, rtol=0, atol=1e-7 * np.abs(f).max(),
                               err_msg="J dz = -F: O(t^2) differences and GMRES 1e-9")
    p = np.array([-1e7, 0.0, 1e8, 1e9])
    dq = np.imag(prob.flux.reduced(p + 1e-20j)) / 1e-20  # complex step
    np.testing.assert_allclose(dq, prob.flux.fluidity(p), rtol=1e-12,
                               err_msg="fluidity = dq/dp = eta0/eta (exact to rounding)")
    np.testing.assert_allclose(prob.flux.fluidity(p),
                               scene.lubricant.viscosity / prob.flux.viscosity(p), rtol=1e-12)


def test_xi_complex_step_equals_analytic_derivative():
    from bearing_fem.physics.reynolds import upwind_factor

    x = np.array([-50.0, -3.0, -1e-3, 0.0, 1e-3, 0.5, 2.0, 39.0, 41.0, 1e3])
    s = 1e-20
    d = np.imag(upwind_factor(x + 1j * s)) / s
    xm = x[(np.abs(x) >= 1e-2) & (np.abs(x) <= 40)]
    exact = 1 / xm**2 - 1 / np.sinh(xm) ** 2
    np.testing.assert_allclose(d[(np.abs(x) >= 1e-2) & (np.abs(x) <= 40)], exact, rtol=1e-10,
                               err_msg="xi' = 1/x^2 - 1/sinh^2 x")
    np.testing.assert_allclose(np.real(upwind_factor(x + 1j * s)),
                               upwind_factor(x), rtol=0, atol=0,
                               err_msg="real part of the complex step is the real value")


def test_lightly_loaded_ball_keeps_its_outlet_in_the_domain(far_field_on_given_domain):
    """A 12.7 mm steel ball at 0.3 N, 2 m/s, 0.05 Pa s (Moes M = 0.81, L = 15.7): the
    pressure zone reaches about 10 Hertz radii downstream; the default domain ended at
    1.5 a_x, cut it there and gave h_central 2.405e-6 m against 2.558e-6 m with the outlet
    at 1, 2 or 4 hydrodynamic lengths sqrt(2 rx h) (-6 %, both with p = 0 on the edges).
    The default domain now carries Kapitsa's far field on its edges (M < 15,
    tests/test_point_far_field.py): h_central 3.903e-6 m, and with the outlet 4 times
    further (the same far field) 3.904e-6 m."""
    import bearing_fem as bf
    from bearing_fem.contacts.point import default_ranges

    def scene(x_range=None, nodes=None, y_range=None):
        d = dict(contact=dict(kind="point", rx=0.00635, ry=0.00635),
                 materials=dict(reduced_modulus=2.3e11),
                 lubricant=dict(viscosity=0.05, piezo=2e-8),
                 kinematics=dict(u1=2.0, u2=2.0), load=dict(force=0.3),
                 model=dict(elasticity="half-space"))
        if x_range:
            d["mesh"] = dict(x_range=list(x_range), y_range=list(y_range), nodes=nodes)
        return bf.Scene.from_dict(d)

    light = scene()
    (x0, x1), y_range = default_ranges(light)
    assert x1 > 5.0, "the outlet end follows the hydrodynamic length at light load"
    r = bf.solve(light)
    assert r.success and "load_beyond_domain" in r.quantities, r.message
    # the longer domain with the default domain's far field on its edges too (a given
    # range otherwise keeps p = 0)
    far_field_on_given_domain()
    long = bf.solve(scene((x0, 4.0 * x1), [193, 129], y_range))
    assert long.success and "load_beyond_domain" in long.quantities, long.message
    np.testing.assert_allclose(r.quantities["h_central"], long.quantities["h_central"],
                               rtol=2e-3, err_msg="an outlet four times further changes "
                               "the film (measured -3.3e-4 with the far field, 4e-4 with "
                               "p = 0 edges; the cut domain was 6 % off)")
