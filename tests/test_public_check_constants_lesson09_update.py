"""The numbers stored in lesson 09's public checks of filter_update, recomputed from their definitions: the answer
at the checks' fixed inputs both with the measurement Jacobian by central differences of (R Exp(ε))ᵀ g_w (the MAP
cost's minimiser and the inverse of half its Hessian, as the checks once computed them) and in closed form (the Kalman gain)."""

import numpy as np
import pytest

from coursekit.checks import lesson09_update as checks
from coursekit.lie import Exp, skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _map_update(R, P, y, g_w, Rn):
    """Minimiser, and inverse of half the Hessian, of |ε|²_P⁻¹ + |y - h(0) - H ε|²_Rn⁻¹, H by central differences."""
    H = _central(lambda e: (R @ Exp(e)).T @ g_w, 3)
    information = np.linalg.inv(P) + H.T @ np.linalg.solve(Rn, H)
    step = np.linalg.solve(information, H.T @ np.linalg.solve(Rn, y - R.T @ g_w))
    return step, np.linalg.inv(information)


def _step(H):
    """The Kalman correction K (y - Rᵀ g_w) with the measurement Jacobian H, at the checks' inputs."""
    P, Rn = checks.P0, checks.R_NOISE
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + Rn)
    return K @ (checks.Y_ACCEL - checks.QUARTER_X.T @ checks.GRAVITY_W)


def test_the_update():
    R, P, g_w = checks.QUARTER_X, checks.P0, checks.GRAVITY_W
    H = skew(R.T @ g_w)  # (R Exp(ε))ᵀ g_w = Exp(-ε) Rᵀ g_w ≈ Rᵀ g_w + [Rᵀ g_w]× ε
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + checks.R_NOISE)
    assert np.allclose(checks.UPDATE_STEP, _step(H), rtol=0, atol=1e-15)
    assert np.allclose(checks.UPDATE_P_NEW, (np.eye(3) - K @ H) @ P, rtol=0, atol=1e-16)
    step, P_new = _map_update(R, P, checks.Y_ACCEL, g_w, checks.R_NOISE)  # the differences are good to 1e-12
    assert np.allclose(checks.UPDATE_STEP, step, rtol=0, atol=1e-12)
    assert np.allclose(checks.UPDATE_P_NEW, P_new, rtol=0, atol=1e-14)


def test_the_update_slips():
    R, g_w = checks.QUARTER_X, checks.GRAVITY_W
    predicted = R.T @ g_w
    assert np.allclose(checks.UPDATE_SIGN_STEP, _step(-skew(predicted)), rtol=0, atol=1e-12)
    assert np.allclose(checks.UPDATE_NO_R_STEP, _step(skew(g_w)), rtol=0, atol=1e-12)
    assert np.allclose(checks.UPDATE_LEFT_STEP, _step(R.T @ skew(g_w)), rtol=0, atol=1e-12)


def test_the_answer_at_a_generic_attitude():
    """The exact update (H = [Rᵀ g_w]×, held against central differences of (R Exp(ε))ᵀ g_w) at the generic attitude."""
    from coursekit.lie import Exp

    R, g_w, P, Rn, y = (
        Exp(checks.UPDATE_GENERIC_ROTATION),
        checks.GRAVITY_W,
        checks.P0,
        checks.R_NOISE,
        checks.UPDATE_GENERIC_Y,
    )
    H = skew(R.T @ g_w)
    h = 1e-6
    numeric = np.column_stack([((R @ Exp(h * e)).T @ g_w - (R @ Exp(-h * e)).T @ g_w) / (2 * h) for e in np.eye(3)])
    assert np.allclose(H, numeric, rtol=0, atol=1e-8)
    information = np.linalg.inv(P) + H.T @ np.linalg.solve(Rn, H)
    step = np.linalg.solve(information, H.T @ np.linalg.solve(Rn, y - R.T @ g_w))
    assert np.allclose(checks.UPDATE_GENERIC_STEP, step, rtol=0, atol=1e-14)
    assert np.allclose(checks.UPDATE_GENERIC_P_NEW, np.linalg.inv(information), rtol=0, atol=1e-17)
