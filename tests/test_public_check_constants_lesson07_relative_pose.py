"""The numbers stored in lesson 07's public checks of relative_pose, recomputed from their definitions."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation


from coursekit.checks import lesson07_relative_pose as checks

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def pose(R, t):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, t
    return T


def test_the_poses_and_the_slips():
    qz = Rotation.from_rotvec([0.0, 0.0, np.pi / 2]).as_matrix()
    qx = Rotation.from_rotvec([np.pi / 2, 0.0, 0.0]).as_matrix()
    T_wa, T_wb = pose(qz, [1.0, 2.0, 0.0]), pose(qz @ qx, [3.0, -1.0, 2.0])
    assert np.allclose(checks.T_WA, T_wa, atol=1e-15) and np.allclose(checks.T_WB, T_wb, atol=1e-15)
    inv = np.linalg.inv
    assert np.allclose(checks.T_AB, inv(T_wa) @ T_wb, atol=1e-14)
    assert np.allclose(checks.COLLEAGUE_RESULT, T_wb @ inv(T_wa), atol=1e-14)
    assert np.allclose(checks.TRANSPOSED, T_wa.T @ T_wb, atol=1e-14)
    assert np.allclose(checks.REVERSED, inv(T_wb) @ T_wa, atol=1e-14)
    assert np.allclose(checks.UNROTATED, pose(qz.T @ qz @ qx, T_wb[:3, 3] - T_wa[:3, 3]), atol=1e-14)
