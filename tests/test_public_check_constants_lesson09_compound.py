"""The numbers stored in lesson 09's public checks of compound_pose_covariance, recomputed from their definitions
(the adjoint written out by blocks here, checked against its defining identity); the answer's S also by central
differences of its definition, T1 Exp(ξ1) T2 Exp(ξ2) = T Exp(ξ), as the checks once computed it."""

import numpy as np
import pytest

from coursekit.checks import lesson09_compound as checks
from coursekit.lie import ExpSE3, LogSE3, skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def adjoint(T):
    R, t = T[:3, :3], T[:3, 3]
    return np.block([[R, skew(t) @ R], [np.zeros((3, 3)), R]])


def _linearised(T1, S1, T2, S2, h=1e-6):
    """The first-order covariance of ξ in T1 Exp(ξ1) T2 Exp(ξ2) = T Exp(ξ), by central differences."""
    T = T1 @ T2
    inverse = np.linalg.inv(T)

    def error(x):
        return LogSE3(inverse @ T1 @ ExpSE3(x[:6]) @ T2 @ ExpSE3(x[6:]))

    J = np.column_stack([(error(h * e) - error(-h * e)) / (2.0 * h) for e in np.eye(12)])
    return J[:, :6] @ S1 @ J[:, :6].T + J[:, 6:] @ S2 @ J[:, 6:].T


def same(stored, computed, tol=1e-12):
    assert np.max(np.abs(np.asarray(stored) - computed)) <= tol * max(1.0, np.max(np.abs(computed)))


def test_poses_and_adjoint():
    same(checks.T1, ExpSE3([1.0, -0.5, 0.3, 0.2, -0.4, 0.9]))
    same(checks.T2, ExpSE3([0.4, 1.2, -0.8, -0.7, 0.3, 0.5]))
    same(checks.T_SWAPPED, checks.T2 @ checks.T1)
    xi = np.array([0.1, -0.2, 0.3, 0.05, 0.1, -0.02])
    T = checks.T2
    assert np.allclose(T @ ExpSE3(xi) @ np.linalg.inv(T), ExpSE3(adjoint(T) @ xi), atol=1e-12)


def test_the_slips():
    T1, T2, S1, S2 = checks.T1, checks.T2, checks.S1, checks.S2
    A, B, C = adjoint(np.linalg.inv(T2)), adjoint(T2), adjoint(np.linalg.inv(T1))
    D = np.kron(np.eye(2), T2[:3, :3].T)
    same(checks.S_NO_TRANSPORT, S1 + S2)
    same(checks.S_WRONG_WAY, B @ S1 @ B.T + S2)
    same(checks.S_OTHER_POSE, C @ S1 @ C.T + S2)
    same(checks.S_ROTATION_ONLY, D @ S1 @ D.T + S2)
    same(checks.S_ONE_SIDED, A @ S1 + S2)
    same(_linearised(T1, S1, T2, S2), A @ S1 @ A.T + S2, tol=1e-9)


def test_the_answer():
    T1, T2, S1, S2 = checks.T1, checks.T2, checks.S1, checks.S2
    A = adjoint(np.linalg.inv(T2))  # ξ1 crosses T2: T1 Exp(ξ1) T2 = T1 T2 Exp(Ad(T2⁻¹) ξ1)
    assert np.allclose(checks.COMPOUND_S, A @ S1 @ A.T + S2, rtol=0, atol=1e-16)
    assert np.allclose(checks.COMPOUND_S, _linearised(T1, S1, T2, S2), rtol=0, atol=1e-11)
