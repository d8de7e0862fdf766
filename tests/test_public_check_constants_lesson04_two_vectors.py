"""The numbers stored in lesson 04's public checks of quat_from_two_vectors, recomputed from their definitions."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson04_two_vectors as checks

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def quat(rotvec):
    return Rotation.from_rotvec(rotvec).as_quat(scalar_first=True)


def test_answers():
    assert np.allclose(checks.X_ONTO_Y, quat([0.0, 0.0, np.pi / 2]), atol=1e-15)
    assert np.allclose(checks.EIGHTH, quat([0.0, 0.0, np.pi / 4]), atol=1e-15)


def test_slips():
    theta, u = np.pi / 2, np.array([0.0, 0.0, 1.0])
    assert np.allclose(checks.X_ONTO_Y_FULL_ANGLE, np.concatenate([[np.cos(theta)], np.sin(theta) * u]), atol=1e-15)
    assert np.allclose(checks.X_ONTO_Y_REVERSED, quat([0.0, 0.0, -np.pi / 2]), atol=1e-15)
    a, b = np.array([2.0, 0.0, 0.0]), np.array([3.0, 3.0, 0.0])
    raw = np.concatenate([[1.0 + a @ b], np.cross(a, b)])
    assert np.allclose(checks.EIGHTH_UNNORMALISED, raw / np.linalg.norm(raw), atol=1e-15)


def test_the_answer_at_a_micro_radian():
    a, b = np.array([0.3, -1.2, 2.0]), np.array([0.3, -1.2 + 2e-6, 2.0 + 1.2e-6])
    truth = Rotation.align_vectors([b / np.linalg.norm(b)], [a / np.linalg.norm(a)])[0].as_quat(scalar_first=True)
    assert np.allclose(checks.MICRO, truth * np.sign(truth[0]), atol=1e-15)
