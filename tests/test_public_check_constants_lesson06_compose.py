"""The hand-written quarter turns of lesson 06's public checks of jacobians_of_compose and jacobian_of_inverse.

The rotations themselves are recomputed here from scipy; and each usual slip, written out here by its formula,
gets its own hint from the checks, which recognise it by what would pass instead (never by the formula).
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


def test_each_slip_gets_its_own_hint_at_the_checks_inputs():
    R1, R2 = checks.QUARTER_Z, checks.QUARTER_X
    assert np.allclose(checks._compose_numeric(R1, R2), [R2.T, np.eye(3)], atol=1e-9)  # the answer (R2ᵀ, I)
    identity = np.eye(3)
    slips = {  # each slip as the function a student would write, since a hint may call it on other inputs
        "transpose": lambda A, B: (B, identity),
        "ignores R2": lambda A, B: (identity, identity),
        "left": lambda A, B: (identity, A),
        "swapped": lambda A, B: (identity, B.T),
        "wrong factor": lambda A, B: (A.T, identity),
    }
    compose_hints = {name: checks._compose_hint(slip, *slip(R1, R2), R1, R2) for name, slip in slips.items()}
    assert None not in compose_hints.values() and len(set(compose_hints.values())) == len(slips), compose_hints
    R = checks.PERMUTATION
    assert np.allclose(checks._inverse_numeric(R), -R, atol=1e-9)  # the answer -R
    inverse_slips = (lambda X: -X.T, lambda X: -identity, lambda X: X, lambda X: X.T)
    inverse_hints = [checks._inverse_hint(slip, slip(R), R) for slip in inverse_slips]
    assert None not in inverse_hints and len(set(inverse_hints)) == 4, inverse_hints
