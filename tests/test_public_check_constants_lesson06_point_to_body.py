"""Lesson 06's public checks of jacobian_point_to_body store no slip: each one, written out here by its formula, is
told apart at run time by what the finite differences of another map give instead."""

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from coursekit.checks import lesson06_point_to_body as checks
from coursekit.lie import skew

pytestmark = pytest.mark.blas_sensitive  # stored numbers of BLAS/LAPACK: run again under another kernel by .ci/run


def test_the_quarter_turn():
    R = checks.QUARTER_Z
    assert np.allclose(R, Rotation.from_rotvec([0.0, 0.0, np.pi / 2]).as_matrix(), atol=1e-15)


def test_no_answer_is_stored():
    """Besides the check's inputs, the module holds no 3×3 array: neither the answer nor a rearrangement of it."""
    arrays = {name: value for name, value in vars(checks).items() if isinstance(value, np.ndarray)}
    assert set(arrays) == {"QUARTER_Z", "P_WORLD"}, sorted(arrays)


@pytest.mark.parametrize(
    "R, p",
    [
        (checks.QUARTER_Z, checks.P_WORLD),
        (Rotation.from_rotvec([0.4, -0.9, 0.3]).as_matrix(), np.array([0.3, 1.7, -2.1])),
    ],
)
def test_each_slip_gets_its_hint(R, p):
    answer = skew(R.T @ p)
    slips = {
        checks.LEFT_HINT: R.T @ skew(p),
        checks.SIGN_HINT: -answer,
        checks.NO_R_HINT: skew(p),
        checks.FORWARD_HINT: -R @ skew(p),
    }
    for hint, slip in slips.items():
        assert checks._slip_hint(slip, R, p) == hint
    assert checks._slip_hint(answer, R, p) is None
    assert checks._slip_hint(answer + 1e-3, R, p) is None
