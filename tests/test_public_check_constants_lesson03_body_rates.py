"""The numbers stored in lesson 03's public checks of body_angular_velocity, recomputed from their definitions."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson03_body_rates as checks
from coursekit.lie import skew, unskew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def test_the_rolled_body_and_its_spin():
    R = Rotation.from_rotvec([np.pi / 2, 0.0, 0.0]).as_matrix()
    assert np.allclose(checks.ROLLED, R, atol=1e-15)
    omega_w = np.array([0.0, 0.0, 1.0])
    R_dot = skew(omega_w) @ R  # lesson 03: dR/dt = [ω_w]× R
    assert np.allclose(checks.ROLLED_DOT, R_dot, atol=1e-15)
    h = 1e-7  # and the same by a finite difference
    assert np.allclose(checks.ROLLED_DOT, (Rotation.from_rotvec(h * omega_w).as_matrix() @ R - R) / h, atol=1e-6)
    assert np.allclose(checks.WORLD_RATE, omega_w)
    assert np.allclose(checks.BODY_RATE, R.T @ omega_w, atol=1e-15)  # ω_w = R ω_b


def test_the_slips():
    R, R_dot = checks.ROLLED, checks.ROLLED_DOT
    assert np.allclose(checks.WORLD_RATE, unskew(R_dot @ R.T), atol=1e-15)
    assert np.allclose(-checks.BODY_RATE, unskew(R_dot.T @ R), atol=1e-15)
    assert np.allclose(checks.VEE_OF_R_DOT, unskew(R_dot), atol=1e-15)
    assert np.allclose(checks.TURNED_TWICE, R.T @ unskew(R.T @ R_dot), atol=1e-15)


def test_the_generic_spin():
    R, omega_b, h = checks.GENERIC_R, checks.GENERIC_RATE, 1e-6
    assert np.allclose(checks.GENERIC_R_DOT, R @ skew(omega_b), rtol=0.0, atol=1e-15)  # R(t) = R Exp(t ω_b), at t = 0
    central = R @ Rotation.from_rotvec(h * omega_b).as_matrix() - R @ Rotation.from_rotvec(-h * omega_b).as_matrix()
    assert np.allclose(checks.GENERIC_R_DOT, central / (2 * h), rtol=0.0, atol=1e-9)
