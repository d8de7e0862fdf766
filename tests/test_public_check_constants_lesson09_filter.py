"""The numbers stored in lesson 09's public checks of filter_predict and attitude_nees, recomputed from their
definitions: the prediction's covariance both by central differences of the definition of the new error (as the
checks once computed it) and in closed form, F P Fᵀ + G Q Gᵀ with F = Exp(-ω Δt) and G = J_r(ω Δt) Δt."""

import numpy as np
import pytest

from coursekit.checks import lesson09_filter as checks
from coursekit.lie import Exp, JrSE3, Log, skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _predicted_covariance(R, P, omega, dt, Q):
    """First-order covariance of ε' with R Exp(ω Δt) Exp(ε') = R Exp(ε) Exp((ω - n) Δt), by central differences."""
    R_new = R @ Exp(omega * dt)
    J = _central(lambda x: Log(R_new.T @ R @ Exp(x[:3]) @ Exp((omega - x[3:]) * dt)), 6)
    return J[:, :3] @ P @ J[:, :3].T + J[:, 3:] @ Q @ J[:, 3:].T


def _jr(phi):
    """The right Jacobian of SO(3) at phi: Σ (-[φ]×)^k / (k+1)!, summed until the terms vanish (|φ| ≤ π here)."""
    term, total = np.eye(3), np.eye(3)
    for k in range(1, 40):
        term = term @ (-skew(phi)) / (k + 1)
        total = total + term
    return total


def _exact_covariance(P, omega, dt, Q):
    """F P Fᵀ + G Q Gᵀ: the old error crosses the step, F = Exp(-ω Δt); the noise enters through G = J_r(ω Δt) Δt."""
    F, G = Exp(-omega * dt), _jr(omega * dt) * dt
    return F @ P @ F.T + G @ Q @ G.T


def test_the_prediction():
    P, Q, dt = checks.P0, checks.Q_GYRO, checks.DT
    assert np.allclose(
        _jr(checks.OMEGA * dt), JrSE3(np.concatenate([np.zeros(3), checks.OMEGA * dt]))[3:, 3:], rtol=0, atol=1e-14
    )
    assert np.allclose(checks.PREDICT_P_NEW, _exact_covariance(P, checks.OMEGA, dt, Q), rtol=0, atol=1e-16)
    numeric = _predicted_covariance(checks.QUARTER_Z, P, checks.OMEGA, dt, Q)  # good to 1e-11
    assert np.allclose(checks.PREDICT_P_NEW, numeric, rtol=0, atol=1e-11)


def test_the_prediction_at_every_step():
    P, Q, dt = checks.P0, checks.Q_GYRO, checks.DT
    axis = checks.OMEGA / np.linalg.norm(checks.OMEGA)
    assert checks.PREDICT_SWEEP_P_NEW.shape == (len(checks.STEPS), 3, 3)
    for step, stored in zip(checks.STEPS, checks.PREDICT_SWEEP_P_NEW):
        omega = step / dt * axis
        assert np.allclose(stored, _exact_covariance(P, omega, dt, Q), rtol=0, atol=1e-16), step
        numeric = _predicted_covariance(checks.QUARTER_Z, P, omega, dt, Q)
        assert np.allclose(stored, numeric, rtol=0, atol=1e-11), step


def test_the_prediction_slips():
    P, Q, dt = checks.P0, checks.Q_GYRO, checks.DT
    step = checks.OMEGA * dt
    F = Exp(-step)  # the old error crosses the step
    G = JrSE3(np.concatenate([np.zeros(3), step]))[3:, 3:] * dt  # the noise through the right Jacobian
    assert np.allclose(checks.PREDICT_NOT_CARRIED, P + G @ Q @ G.T, atol=1e-15)
    assert np.allclose(checks.PREDICT_WRONG_WAY, F.T @ P @ F + G @ Q @ G.T, atol=1e-15)
    assert np.allclose(checks.PREDICT_NOISE_SHORT_STEP_ONLY, F @ P @ F.T + dt * dt * Q, atol=1e-15)
    assert np.allclose(checks.PREDICT_NOISE_DT, F @ P @ F.T + G @ Q @ G.T / dt, atol=1e-15)
    assert np.allclose(checks.PREDICT_NO_NOISE, F @ P @ F.T, atol=1e-15)
    assert np.allclose(checks.PREDICT_NOISE_OLD_AXES, F @ P @ F.T + G.T @ Q @ G, atol=1e-15)


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
