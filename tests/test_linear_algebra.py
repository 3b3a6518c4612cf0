"""The dense and sparse kernels behind the Newton steps: the line contact's dense Jacobian
(row blocks, float32) and the point contact's gathered free-node pattern
(bearing_fem.contacts.line, point_grid)."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
import scipy.sparse as sp

from bearing_fem.contacts import line
from bearing_fem.contacts.point_grid import FreePattern, PointGrid

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "studies"))
from line_ehl_map import scene_for  # noqa: E402


def _line_problem_at_hertz(nodes: int):
    model = line.LineModel(scene_for(100, 10, nodes))
    level = model.levels()[-1]
    problem = model.problem(level)
    z = model.initial_guess(level, problem)
    problem.prepare(z)
    return problem, z


@pytest.mark.parametrize("block_entries", [2**17, 1000, 1])
def test_dense_line_jacobian_equals_the_assembled_one(monkeypatch, block_entries):
    # the row-blocked product A_h C gives the Jacobian of the sparse-dense assembly for
    # any block size (one block, blocks with a remainder, one row per block)
    monkeypatch.setattr(line, "DENSE_JACOBIAN_BLOCK_ENTRIES", block_entries)
    problem, z = _line_problem_at_hertz(101)
    blocks = problem._blocks(z)
    shift = 0.3
    fast = problem._dense_jacobian(blocks, shift, np.float64)
    ref = problem._jacobian_from_blocks(*blocks)
    npf = problem.free.size
    ref[np.arange(npf), np.arange(npf)] += shift
    np.testing.assert_allclose(fast, ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max(),
                               err_msg="the same sums in another order: rounding only")
    single = problem._dense_jacobian(blocks, shift, np.float32)
    assert single.dtype == np.float32
    np.testing.assert_allclose(single, ref, rtol=0, atol=1e-6 * np.abs(ref).max(),
                               err_msg="float32 entries: single-precision rounding")


def _gathered(pattern: FreePattern, values: np.ndarray) -> np.ndarray:
    """The dense matrix FreePattern gathers from pattern values (scale 1, diag 0)."""
    data = values[pattern._select]
    return sp.csc_matrix((data, pattern.indices, pattern.indptr),
                         shape=(pattern.size, pattern.size)).toarray()


@pytest.mark.parametrize("mirror", [False, True])
def test_free_pattern_gathers_the_free_block_in_its_order(mirror):
    grid = PointGrid(np.linspace(-1.0, 1.0, 9), np.linspace(0.0 if mirror else -1.0, 1.0, 7))
    asm = grid.assembler
    mask = np.ones(grid.shape, dtype=bool)
    mask[-1, :] = mask[:, 0] = mask[:, -1] = False
    if not mirror:
        mask[0, :] = False
    free = np.flatnonzero(mask.ravel())
    pattern = FreePattern(grid, free)
    values = np.random.default_rng(3).standard_normal(asm.nnz)
    full = sp.csr_matrix((values, asm.indices, asm.indptr), shape=(grid.size, grid.size))
    chosen = free[pattern.perm]
    expected = full.toarray()[np.ix_(chosen, chosen)]  # dense reference, numpy indexing
    np.testing.assert_array_equal(_gathered(pattern, values), expected,
                                  err_msg="the free-free block, permuted, entry for entry")
    assert np.array_equal(np.sort(pattern.perm), np.arange(free.size))
    csc = sp.csc_matrix((values[pattern._select], pattern.indices, pattern.indptr),
                        shape=(pattern.size, pattern.size))
    assert csc.has_sorted_indices, "rows ascending within each column"
    rows = pattern.indices[pattern._diag]
    cols = np.searchsorted(pattern.indptr, pattern._diag, side="right") - 1
    assert np.array_equal(rows, np.arange(free.size)) and np.array_equal(cols, rows), \
        "_diag lists the diagonal entries, row by row"
