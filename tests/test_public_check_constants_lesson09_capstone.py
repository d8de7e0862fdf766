"""The numbers stored in lesson 09's public checks of hand_eye_rotation, recomputed from their definitions.

For each noisy dataset (the checks draw the data themselves, with fixed seeds): σ_X, the first-order spread of
the best estimate, from the information of the good pairs under the data's noise model A_i = X B_i Xᵀ Exp(n_i),
n_i ~ N(0, σ² I): with X = X̂ Exp(δ), X B_i Xᵀ = X̂ B_i X̂ᵀ Exp(X̂ (B_iᵀ - I) δ) to first order, so a pair's
information is (B_i - I)(B_i - I)ᵀ / σ² = (2 I - B_i - B_iᵀ) / σ²; and what two slips return, one equally weighted alignment of the turn
axes of all pairs, and of the first two pairs only (each an SVD with the determinant fix)."""

import numpy as np
import pytest

from coursekit.checks import lesson09_capstone as checks
from coursekit.lie import Exp, Log

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def _aligned(As, Bs):
    a = np.array([Log(A) for A in As])
    b = np.array([Log(B) for B in Bs])
    U, _, Vt = np.linalg.svd(a.T @ b)
    return U @ np.diag([1.0, 1.0, np.linalg.det(U @ Vt)]) @ Vt


def _good_pairs(seed, pairs, outliers):
    """The indices of the pairs the dataset left exact up to noise (it replaces the others by random rotations)."""
    As, Bs, X, _ = checks._dataset(seed, pairs, 0.0, outliers)  # the same draws, without the noise
    return [i for i in range(pairs) if np.allclose(As[i], X @ Bs[i] @ X.T, atol=1e-12)]


@pytest.mark.parametrize("key", sorted(checks.NOISY))
def test_the_spread_and_the_slips(key):
    seed, pairs, sigma, outliers = key
    As, Bs, X_true, figures = checks._dataset(seed, pairs, sigma, outliers)
    assert figures is checks.NOISY[key]
    good = _good_pairs(seed, pairs, outliers)
    assert len(good) == pairs - outliers
    information = sum(2 * np.eye(3) - Bs[i] - Bs[i].T for i in good)
    spread = sigma * np.sqrt(np.trace(np.linalg.inv(information)))
    assert figures["spread"] == pytest.approx(spread, rel=1e-12, abs=0)
    for name, (A, B) in {"all pairs": (As, Bs), "first two": (As[:2], Bs[:2])}.items():
        stored = Exp(figures[name])
        assert np.linalg.norm(Log(stored.T @ _aligned(A, B))) < 1e-12, name
        assert np.linalg.norm(Log(stored.T @ X_true)) > 1e-3, name  # a slip, not the answer
