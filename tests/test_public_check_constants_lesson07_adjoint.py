"""The numbers stored in lesson 07's public checks of the adjoint and the point Jacobian, recomputed from each
slip's definition (and the hand-written quarter turn from scipy), to about 1e-12."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson07_adjoint as checks
from coursekit.lie import skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def same(stored, computed, tol=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    assert np.max(np.abs(stored - computed)) <= tol * max(1.0, np.max(np.abs(computed))), (stored, computed)


def block(top_left, top_right, bottom_left, bottom_right):
    return np.block([[top_left, top_right], [bottom_left, bottom_right]])


def test_hand_written_rotation_and_pose():
    same(checks.QUARTER_Z, Rotation.from_rotvec([0.0, 0.0, np.pi / 2]).as_matrix())
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = checks.QUARTER_Z, checks.SHIFT
    same(checks.T_QUARTER, T)


def test_adjoint_slips():
    R, t, Z = checks.QUARTER_Z, checks.SHIFT, np.zeros((3, 3))
    same(checks.ADJ_ROTATION_FIRST, block(R, Z, skew(t) @ R, R))
    same(checks.ADJ_NO_COUPLING, block(R, Z, Z, R))
    same(checks.ADJ_COUPLING_WITHOUT_R, block(R, skew(t), Z, R))
    same(checks.ADJ_COUPLING_SIGN, block(R, -skew(t) @ R, Z, R))
    same(checks.ADJ_COUPLING_R_FIRST, block(R, R @ skew(t), Z, R))


def test_point_jacobian_slips():
    R, t, p = checks.QUARTER_Z, checks.SHIFT, checks.POINT
    same(checks.JTP_ROTATION_FIRST, np.hstack([-R @ skew(p), R]))
    same(checks.JTP_TRANSLATION_I, np.hstack([np.eye(3), -R @ skew(p)]))
    same(checks.JTP_LEFT, np.hstack([np.eye(3), -skew(R @ p + t)]))
    same(checks.JTP_SIGN, np.hstack([R, R @ skew(p)]))
    same(checks.JTP_WORLD_ROTATION, np.hstack([R, -skew(R @ p)]))


def test_the_twists_of_the_jacobian_checks_have_the_angles_they_name():
    assert abs(np.linalg.norm(checks.XI_TINY[3:]) - 7e-7) < 1e-12
    assert abs(np.linalg.norm(checks.XI_MODERATE[3:]) - 1.0) < 0.05
    assert abs(np.linalg.norm(checks.XI_MODERATE[:3]) - 2.0) < 0.05
    assert abs(np.linalg.norm(checks.XI_LARGE[3:]) - 3.08) < 0.005 and np.linalg.norm(checks.XI_LARGE[3:]) < np.pi
    assert abs(np.linalg.norm(checks.XI_LARGE[:3]) - 37.0) < 0.5
