"""The numbers stored in the public checks of lesson 09, recomputed from each slip's definition.

The public checks are shipped to students, so they carry the values of the usual slips at their fixed inputs
as literals instead of the formulas. This test recomputes every literal from its definition (and the hand-written
quarter turns from scipy) and requires agreement to about 1e-12.
"""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson09 as checks
from coursekit.lie import skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def same(stored, computed, tol=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    assert np.max(np.abs(stored - computed)) <= tol * max(1.0, np.max(np.abs(computed))), (stored, computed)


def quarter(axis):
    return Rotation.from_rotvec(np.pi / 2 * np.eye(3)[axis]).as_matrix()


def test_hand_written_rotations_and_pose():
    same(checks.QUARTER_X, quarter(0))
    same(checks.QUARTER_Y, quarter(1))
    same(checks.QUARTER_Z, quarter(2))
    same(checks.PERMUTATION, quarter(2) @ quarter(0))
    same(checks.PERMUTATION, Rotation.from_rotvec(2 * np.pi / 3 * np.ones(3) / np.sqrt(3)).as_matrix())
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = checks.QUARTER_Z, checks.SHIFT
    same(checks.T_QUARTER, T)


def exp(w):
    return Rotation.from_rotvec(w).as_matrix()


def test_gyro_answers_and_slips():
    same(checks.QUARTER_BODY_Z, quarter(0) @ exp([0.0, 0.0, 50 * 0.02 * np.pi / 2]))
    same(checks.QUARTER_WORLD_Z, exp([0.0, 0.0, 50 * 0.02 * np.pi / 2]) @ quarter(0))
    same(checks.GYRO_NO_DT, quarter(0) @ exp([0.0, 0.0, 50 * np.pi / 2]))
    same(checks.GYRO_X_THEN_Y, quarter(0) @ quarter(1))
    same(checks.GYRO_Y_THEN_X, quarter(1) @ quarter(0))
    same(checks.GYRO_SUMMED, exp([np.pi / 2, np.pi / 2, 0.0]))


def test_point_covariance_and_slips():
    R, S, p = checks.PERMUTATION, checks.SIGMA, checks.COV_P
    J = -R @ skew(p)
    same(checks.COV_POINT, J @ S @ J.T)
    same(checks.COV_POINT_NO_R, skew(p) @ S @ skew(p).T)
    same(checks.COV_POINT_LEFT, skew(R @ p) @ S @ skew(R @ p).T)
    same(checks.COV_POINT_TURNED_SIGMA, R @ S @ R.T)
    same(checks.COV_POINT_ONE_SIDED, J @ S)
    same(checks.COV_POINT_TRANSPOSED, J.T @ S @ J)


@pytest.mark.parametrize("samples", [200_000])
def test_left_to_right_covariance_and_slips(samples):
    R, S = checks.PERMUTATION, checks.SIGMA_LEFT
    same(checks.COV_RIGHT, R.T @ S @ R)
    same(checks.COV_RIGHT_WRONG_WAY, R @ S @ R.T)
    same(checks.COV_RIGHT_ONE_SIDED, R.T @ S)
    same(checks.COV_RIGHT_OTHER_SIDE, S @ R)
    # the stored answer is also what sampling the definition gives: Exp(eps_L) R = R Exp(eps_R)
    eps_left = np.random.default_rng(1).multivariate_normal(np.zeros(3), S, size=samples)
    eps_right = Rotation.from_matrix(R.T @ Rotation.from_rotvec(eps_left).as_matrix() @ R).as_rotvec()
    assert np.max(np.abs(np.cov(eps_right.T) - checks.COV_RIGHT)) < 0.03 * np.max(np.abs(checks.COV_RIGHT))
