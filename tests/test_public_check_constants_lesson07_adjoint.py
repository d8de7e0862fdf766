"""The numbers stored in lesson 07's public checks of the adjoint and the point Jacobian: the hand-written quarter
turn and shifts, recomputed with scipy, and the twists of the Jacobian checks; no slip's value is stored."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson07_adjoint as checks

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def same(stored, computed, tol=1e-12):
    stored, computed = np.asarray(stored, dtype=float), np.asarray(computed, dtype=float)
    assert stored.shape == computed.shape
    assert np.max(np.abs(stored - computed)) <= tol * max(1.0, np.max(np.abs(computed))), (stored, computed)


def test_hand_written_rotation_and_pose():
    same(checks.QUARTER_Z, Rotation.from_rotvec([0.0, 0.0, np.pi / 2]).as_matrix())
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = checks.QUARTER_Z, checks.SHIFT
    same(checks.T_QUARTER, T)


def test_the_unturned_pose_has_the_same_shift():
    T = np.eye(4)
    T[:3, 3] = checks.SHIFT
    same(checks.T_SHIFT, T)


def test_no_answer_is_stored():
    """Slips are told apart at run time: the module keeps no 6×6 or 3×6 matrix (a rearranged answer would be one)."""
    stored = [value for value in vars(checks).values() if isinstance(value, np.ndarray)]
    assert all(value.shape not in ((6, 6), (3, 6)) for value in stored), [value.shape for value in stored]


def test_the_twists_of_the_jacobian_checks_have_the_angles_they_name():
    assert abs(np.linalg.norm(checks.XI_TINY[3:]) - 7e-7) < 1e-12
    assert abs(np.linalg.norm(checks.XI_MODERATE[3:]) - 1.0) < 0.05
    assert abs(np.linalg.norm(checks.XI_MODERATE[:3]) - 2.0) < 0.05
    assert abs(np.linalg.norm(checks.XI_LARGE[3:]) - 3.08) < 0.005 and np.linalg.norm(checks.XI_LARGE[3:]) < np.pi
    assert abs(np.linalg.norm(checks.XI_LARGE[:3]) - 37.0) < 0.5
