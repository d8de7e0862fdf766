"""The numbers stored in lesson 09's public checks of filter_update, recomputed from their definitions."""

import numpy as np
import pytest

from coursekit.checks import lesson09_update as checks
from coursekit.lie import skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def _step(H):
    """The Kalman correction K (y - Rᵀ g_w) with the measurement Jacobian H, at the checks' inputs."""
    P, Rn = checks.P0, checks.R_NOISE
    K = P @ H.T @ np.linalg.inv(H @ P @ H.T + Rn)
    return K @ (checks.Y_ACCEL - checks.QUARTER_X.T @ checks.GRAVITY_W)


def test_the_update_slips():
    R, g_w = checks.QUARTER_X, checks.GRAVITY_W
    predicted = R.T @ g_w
    assert np.allclose(checks.UPDATE_SIGN_STEP, _step(-skew(predicted)), rtol=0, atol=1e-12)
    assert np.allclose(checks.UPDATE_NO_R_STEP, _step(skew(g_w)), rtol=0, atol=1e-12)
    assert np.allclose(checks.UPDATE_LEFT_STEP, _step(R.T @ skew(g_w)), rtol=0, atol=1e-12)
