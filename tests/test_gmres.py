"""The right-preconditioned GMRES of the Newton steps (bearing_fem.numerics.newton)."""
import math

import numpy as np
import pytest

from bearing_fem.numerics.newton import gmres_right


def _system(n: int = 40, seed: int = 3):
    rng = np.random.default_rng(seed)
    a = np.eye(n) * 4.0 + rng.normal(scale=0.3, size=(n, n))
    b = rng.normal(size=n)
    return a, b


def test_gmres_solves_a_preconditioned_system():
    a, b = _system()
    d = np.diag(a)
    x, its, rel = gmres_right(lambda u: a @ u, lambda r: r / d, b, rtol=1e-10,
                              max_iterations=60)
    np.testing.assert_allclose(a @ x, b, rtol=0, atol=1e-8 * np.linalg.norm(b),
                               err_msg="GMRES to 1e-10 relative must solve A x = b")
    assert rel <= 1e-10 and 0 < its <= 40, (its, rel)


@pytest.mark.parametrize("where", ["start", "later"])
def test_non_finite_preconditioner_is_a_failed_solve_not_a_lapack_message(where, capfd):
    """Singular single-precision factors give inf/NaN; GMRES reports rel = inf (the
    callers treat that as a failed linear solve) and hands no NaN to LAPACK, whose
    least-squares driver would print 'On entry to DLASCL ...' to the terminal."""
    a, b = _system()
    calls = [0]

    def bad(r):
        calls[0] += 1
        if where == "start" or calls[0] > 3:
            return np.full_like(r, np.nan)
        return r.copy()

    x, its, rel = gmres_right(lambda u: a @ u, bad, b, rtol=1e-10, max_iterations=60)
    assert math.isinf(rel), f"a non-finite preconditioner must give rel = inf, got {rel}"
    assert np.all(np.isfinite(x)), "the returned iterate must stay finite"
    out, err = capfd.readouterr()
    assert "DLASCL" not in out + err, "LAPACK must not see NaN (it prints to stderr)"
