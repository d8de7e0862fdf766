"""The numbers stored in lesson 04's public checks of quat_power, recomputed from their definitions."""

import numpy as np
import pytest

from coursekit.checks import lesson04_powers as checks

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def same(stored, computed, tol=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    assert np.max(np.abs(stored - computed)) <= tol * max(1.0, np.max(np.abs(computed))), (stored, computed)


def test_quaternion_power_slips():
    alpha, axis = 1.0, np.array([0.0, 0.6, 0.8])
    same(checks.Q_TWO_RAD, np.concatenate([[np.cos(alpha)], np.sin(alpha) * axis]))
    same(checks.Q_ONE_FULL_ANGLE, np.concatenate([[np.cos(2 * alpha)], np.sin(2 * alpha) * axis]))
    same(checks.HALF_WITHOUT_UNIT_AXIS, np.sin(0.5 * alpha) * np.linalg.norm(np.sin(alpha) * axis))
    same(checks.HALF_ELEMENTWISE, checks.Q_TWO_RAD**0.5)
