"""The hand-written quarter turns of lesson 06's public checks of jacobians_of_compose and jacobian_of_inverse.

The checks recognise the usual slips by their values at these fixed rotations (products and transposes of them),
so the rotations themselves are recomputed here from scipy.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson06_compose as checks


def quarter(axis):
    return Rotation.from_rotvec(np.pi / 2 * np.eye(3)[axis]).as_matrix()


def test_hand_written_rotations():
    assert np.max(np.abs(checks.QUARTER_X - quarter(0))) < 1e-15
    assert np.max(np.abs(checks.QUARTER_Z - quarter(2))) < 1e-15
    assert np.max(np.abs(checks.PERMUTATION - quarter(2) @ quarter(0))) < 1e-15
    third = Rotation.from_rotvec(2 * np.pi / 3 * np.ones(3) / np.sqrt(3)).as_matrix()
    assert np.max(np.abs(checks.PERMUTATION - third)) < 1e-15


def test_slips_differ_from_the_answer_at_the_checks_inputs():
    """Each stored slip is a different pair from the true Jacobians at (QUARTER_Z, QUARTER_X), so it fails."""
    truth = np.stack([checks.QUARTER_X.T, np.eye(3)])
    for pair, _ in checks.COMPOSE_SLIPS:
        assert np.max(np.abs(np.stack(pair) - truth)) > 0.5
    R = checks.PERMUTATION
    for slip in (-R.T, -np.eye(3), R, R.T):
        assert np.max(np.abs(slip + R)) > 0.5
