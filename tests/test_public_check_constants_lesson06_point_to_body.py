"""The numbers stored in lesson 06's public checks of jacobian_point_to_body, recomputed from their definitions."""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson06_point_to_body as checks
from coursekit.lie import skew


def test_the_slips():
    R, p = checks.QUARTER_Z, checks.P_WORLD
    assert np.allclose(R, Rotation.from_rotvec([0.0, 0.0, np.pi / 2]).as_matrix(), atol=1e-15)
    assert np.allclose(checks.LEFT, R.T @ skew(p), atol=1e-15)
    assert np.allclose(checks.SIGN, -skew(R.T @ p), atol=1e-15)
    assert np.allclose(checks.NO_R, skew(p), atol=1e-15)
    assert np.allclose(checks.FORWARD, -R @ skew(p), atol=1e-15)
