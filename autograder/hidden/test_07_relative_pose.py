"""Hidden checks for lesson 07, section 8: relative_pose (the bug in the colleague's function).

Oracle: the defining property T_wa T_ab = T_wb, with T_ab computed here as inv(T_wa) @ T_wb (numpy's general
inverse, independent of the course's formulas). Core idea (3 of 5 points): the relative pose is T_wa⁻¹ T_wb,
not the colleague's T_wb T_wa⁻¹, for poses that turn by every angle from 1e-12 to π and shift by 1e-6 to
1e3 m, to 1e-12 (1 + |t|). Every test calls relative_pose only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect_array, expect_close, expect_same_with_lists

ANGLES = (1.0, 2.5, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 3.0, np.pi - 1e-9)  # generic turns first
SHIFTS = (1.0, 10.0, 1e-6, 1e-3, 0.5, 1e3, 2.0, 100.0, 3.0)


def _pose(R, t):
    T = np.eye(4)
    T[:3, :3], T[:3, 3] = R, t
    return T


def _hint(got, T_wa, T_wb):
    truth = np.linalg.inv(T_wa) @ T_wb
    slips = [
        (T_wb @ np.linalg.inv(T_wa), hints.RELATIVE_POSE_COLLEAGUE_HINT),
        (T_wa.T @ T_wb, hints.INVERSE_POSE_TRANSPOSE_T1_HINT),
        (np.linalg.inv(T_wb) @ T_wa, hints.RELATIVE_POSE_REVERSED_HINT),
        (_pose(T_wa[:3, :3].T @ T_wb[:3, :3], T_wb[:3, 3] - T_wa[:3, 3]), hints.SHIFT_IN_WORLD_AXES_HINT),
    ]
    for candidate, hint in slips:
        if np.max(np.abs(candidate - truth)) > 1e-9 and explains(got, candidate, truth, floor=1e-12):
            return hint
    return hints.RELATIVE_POSE_CHAIN_HINT


def _random_pose(rng, angle, shift):
    axis, t = rng.normal(size=(2, 3))
    return _pose(Rotation.from_rotvec(angle * axis / np.linalg.norm(axis)).as_matrix(), shift * t / np.linalg.norm(t))


@exercise("relative_pose", weight=3)
def test_relative_pose_chains(student):
    """T_wa T_ab = T_wb for poses turning by 1e-12 … π and shifting by 1e-6 … 1e3 m, to 1e-12 (1 + |t|)"""
    rng = np.random.default_rng(7300)
    for angle, shift in zip(ANGLES, SHIFTS):
        T_wa, T_wb = _random_pose(rng, 1.3, 2.0), _random_pose(rng, angle, shift)
        T_wa[:3, 3] *= shift
        got = expect_array(student.relative_pose(T_wa, T_wb), (4, 4), "relative_pose(T_wa, T_wb)")
        expect_close(
            got,
            np.linalg.inv(T_wa) @ T_wb,
            1e-12,
            f"relative_pose for a turn of {angle:.3g} rad and shifts of about {shift:g} m",
            lambda: _hint(got, T_wa, T_wb),
            scale=1.0 + 3.0 * shift,
        )


@exercise("relative_pose", weight=1)
def test_relative_pose_special_cases(student):
    """a frame seen from itself is the identity; from the world, T_wb itself; and T_ab is the inverse of T_ba"""
    rng = np.random.default_rng(7310)
    T_wa, T_wb = _random_pose(rng, 2.0, 3.0), _random_pose(rng, 0.7, 1.5)
    same = expect_array(student.relative_pose(T_wb, T_wb), (4, 4), "relative_pose(T, T)")
    expect_close(same, np.eye(4), 1e-12, "relative_pose(T, T)", lambda: _hint(same, T_wb, T_wb))
    got = expect_array(student.relative_pose(np.eye(4), T_wb), (4, 4), "relative_pose(I, T_wb)")
    expect_close(got, T_wb, 1e-12, "relative_pose(I, T_wb)", lambda: _hint(got, np.eye(4), T_wb))
    ab = expect_array(student.relative_pose(T_wa, T_wb), (4, 4), "relative_pose(T_wa, T_wb)")
    ba = expect_array(student.relative_pose(T_wb, T_wa), (4, 4), "relative_pose(T_wb, T_wa)")
    expect_close(ab @ ba, np.eye(4), 1e-12, "T_ab T_ba", lambda: _hint(ab, T_wa, T_wb), scale=5.0)


@exercise("relative_pose", weight=1)
def test_relative_pose_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    rng = np.random.default_rng(7320)
    expect_same_with_lists(
        student.relative_pose,
        (_random_pose(rng, 1.0, 2.0), _random_pose(rng, 2.0, 1.0)),
        (4, 4),
        "relative_pose(T_wa, T_wb)",
    )
