"""Hidden checks for lesson 06, section 9: jacobian_point_to_body.

Oracles: the closed form [Rᵀ p_w]× derived here ((R Exp(δ))ᵀ p_w ≈ Rᵀ p_w - [δ]× Rᵀ p_w = Rᵀ p_w + [Rᵀ p_w]× δ)
and central differences of the definition (scipy's Exp). Core idea (3 of 5 points): the right perturbation acts
on the body-frame point Rᵀ p_w, for attitudes at every angle from 1e-12 to π and |p_w| from 1e-6 to 1e3 m, to
1e-12 |p_w|. Every test calls jacobian_point_to_body only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import explains

from .helpers import exercise, expect_array, expect_close, expect_same_with_lists, random_rotations

ANGLES = (1.0, 2.5, 1e-12, 1e-9, 1e-6, 1e-3, 0.1, 3.0, np.pi - 1e-9)  # generic turns first
SIZES = (1.0, 10.0, 1e-6, 1e-3, 0.1, 1e3, 2.0, 50.0, 0.5)


def _skew(v):
    return np.column_stack([np.cross(np.asarray(v, dtype=float), e) for e in np.eye(3)])


def _hint(J, R, p):
    truth = _skew(R.T @ p)
    size = np.linalg.norm(p)
    slips = [
        (R.T @ _skew(p), hints.LEFT_PERTURBATION_POINT_JACOBIAN_HINT),
        (-truth, hints.POINT_TO_BODY_SIGN_HINT),
        (_skew(p), hints.POINT_SEEN_BODY_RT_HINT),
        (
            -R @ _skew(p),
            "that is Exercise 5's answer, which is the Jacobian of R p (body to world); here the map is Rᵀ p_w",
        ),
    ]
    for candidate, hint in slips:
        if np.max(np.abs(candidate - truth)) > 1e-9 * size and explains(
            J / size, candidate / size, truth / size, floor=1e-13
        ):
            return hint
    return (
        "J must match the finite differences of (R Exp(δ))ᵀ p_w column by column: column j is how the body-frame "
        "point moves per radian of turn about the body's axis j"
    )


@exercise("jacobian_point_to_body", weight=3)
def test_point_to_body_exact(student):
    """equals d((R Exp(δ))ᵀ p_w)/dδ at δ = 0 to 1e-12 |p_w|, R at every angle from 1e-12 to π, |p_w| from 1e-6 to 1e3 m"""
    rng = np.random.default_rng(6300)
    for angle, size in zip(ANGLES, SIZES):
        axis, p = rng.normal(size=(2, 3))
        R = Rotation.from_rotvec(angle * axis / np.linalg.norm(axis)).as_matrix()
        p = size * p / np.linalg.norm(p)
        J = expect_array(student.jacobian_point_to_body(R, p), (3, 3), "jacobian_point_to_body(R, p_w)")
        expect_close(
            J,
            _skew(R.T @ p),
            1e-12,
            f"jacobian_point_to_body for a turn of {angle:.3g} rad and |p_w| = {size:g} m",
            lambda: _hint(J, R, p),
            scale=size,
        )


@exercise("jacobian_point_to_body", weight=1)
def test_point_to_body_finite_differences(student):
    """matches central differences of (R Exp(δ))ᵀ p_w to 1e-8 (1 + |p_w|) for 4 attitudes"""
    rng = np.random.default_rng(6310)
    for R in random_rotations(4, 6311):
        p = 3.0 * rng.normal(size=3)
        J = expect_array(student.jacobian_point_to_body(R, p), (3, 3), "jacobian_point_to_body(R, p_w)")
        h = 1e-6
        numeric = np.column_stack(
            [
                (
                    (R @ Rotation.from_rotvec(h * e).as_matrix()).T @ p
                    - (R @ Rotation.from_rotvec(-h * e).as_matrix()).T @ p
                )
                / (2 * h)
                for e in np.eye(3)
            ]
        )
        expect_close(
            J,
            numeric,
            1e-8,
            "jacobian_point_to_body against finite differences",
            lambda: _hint(J, R, p),
            scale=1.0 + np.linalg.norm(p),
        )


@exercise("jacobian_point_to_body", weight=1)
def test_point_to_body_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    expect_same_with_lists(
        student.jacobian_point_to_body,
        (random_rotations(1, 6320)[0], [0.3, -1.2, 2.0]),
        (3, 3),
        "jacobian_point_to_body(R, p_w)",
    )
