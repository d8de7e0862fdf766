"""The numbers stored in lesson 09's public checks of filter_predict and attitude_nees, recomputed from their definitions."""

import numpy as np
import pytest

from coursekit.checks import lesson09_filter as checks
from coursekit.lie import Exp, JrSE3, Log

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def test_the_prediction_slips():
    P, Q, dt = checks.P0, checks.Q_GYRO, checks.DT
    step = checks.OMEGA * dt
    F = Exp(-step)  # the old error crosses the step
    G = JrSE3(np.concatenate([np.zeros(3), step]))[3:, 3:] * dt  # the noise through the right Jacobian
    assert np.allclose(checks.PREDICT_NOT_CARRIED, P + G @ Q @ G.T, atol=1e-15)
    assert np.allclose(checks.PREDICT_WRONG_WAY, F.T @ P @ F + G @ Q @ G.T, atol=1e-15)
    assert np.allclose(checks.PREDICT_NO_JR, F @ P @ F.T + dt * dt * Q, atol=1e-15)
    assert np.allclose(checks.PREDICT_NOISE_DT, F @ P @ F.T + G @ Q @ G.T / dt, atol=1e-15)
    assert np.allclose(checks.PREDICT_NO_NOISE, F @ P @ F.T, atol=1e-15)
    assert np.allclose(checks.PREDICT_LEFT_JACOBIAN, F @ P @ F.T + G.T @ Q @ G, atol=1e-15)


def test_the_nees_numbers():
    L, u = checks.NEES_L, checks.NEES_U
    eps = L @ u
    assert np.isclose(eps @ np.linalg.solve(L @ L.T, eps), 1.69, rtol=0, atol=1e-12)
    assert np.isclose(checks.NEES_SLIP_DIAGONAL, eps @ (eps / np.diag(L @ L.T)), rtol=0, atol=1e-15)
    R_est, P = checks.NEES_R_EST, checks.NEES_P
    R_true = R_est @ Exp([0.6, 0.0, 0.0])
    eps = Log(R_est.T @ R_true)
    world = Log(R_true @ R_est.T)
    difference = Log(R_true) - Log(R_est)
    truth = eps @ np.linalg.solve(P, eps)
    expected = [
        world @ np.linalg.solve(P, world),
        eps @ P @ eps,
        truth / 3.0,
        np.sqrt(truth),
        difference @ np.linalg.solve(P, difference),
    ]
    assert np.isclose(truth, 36.0, rtol=0, atol=1e-9)
    assert np.allclose([value for value, _ in checks.NEES_SLIPS], expected, rtol=0, atol=1e-9)
