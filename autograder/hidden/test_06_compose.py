"""Hidden checks for lesson 06, section 10: the right Jacobians of composition and inversion.

Oracles: finite differences of each Jacobian's definition, Log(f(X)⁻¹ f(X Exp(d))), taken here with scipy's
Rotation, and the exact Jacobians written out here (both definitions hold exactly, not only to first order, so
the answers are held to 1e-12). Core ideas carry at least half of each exercise's points, so the classic mistake
earns at most half: moving the perturbation of R1 across R2 with the adjoint (3 of 5); the sign and the side of
the inverse's Jacobian (3 of 6). Rotations cover every angle from 1e-12 to π. Every test calls the student's
function of its own exercise only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from coursekit import hints
from coursekit.diagnose import FLOAT32_HINT, explains, single_precision_error

from .helpers import exercise, expect, expect_array, expect_close, expect_same_with_lists, random_rotations

ANGLES = (1e-12, 1e-9, 1e-6, 1e-4, 1e-2, 0.3, 1.0, 2.0, 3.0, np.pi - 1e-6, np.pi - 1e-9)


def _exp(w):
    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()


def _log(R):
    return Rotation.from_matrix(np.asarray(R, dtype=float)).as_rotvec()


def _unit(seed, count):
    v = np.random.default_rng(seed).normal(size=(count, 3))
    return v / np.linalg.norm(v, axis=1, keepdims=True)


def _rotations_at_every_angle(seed):
    """One rotation per angle of ANGLES, about seeded random axes."""
    return [_exp(angle * axis) for angle, axis in zip(ANGLES, _unit(seed, len(ANGLES)))]


def _central(f, n, h=1e-6):
    return np.column_stack([(np.asarray(f(h * e)) - np.asarray(f(-h * e))) / (2.0 * h) for e in np.eye(n)])


def _first_explained(got, candidates, truth, floor=1e-12):
    """The hint of the first slip whose value accounts for ``got``; slips within 100 floors of the truth are
    indistinguishable from it on this input and are skipped."""
    for candidate, hint in candidates:
        candidate = np.asarray(candidate, dtype=float)
        if candidate.shape == np.shape(truth) and np.max(np.abs(candidate - truth)) < 100 * floor:
            continue
        if explains(got, candidate, truth, floor=floor):
            return hint
    return ""


# ---------------------------------------------------------------- jacobians_of_compose
def _pair(value, what):
    expect(
        isinstance(value, (tuple, list)) and len(value) == 2,
        f"{what} returned {type(value).__name__}, not a pair (J1, J2)",
        "return J1, J2",
    )
    return expect_array(value[0], (3, 3), f"{what}'s J1"), expect_array(value[1], (3, 3), f"{what}'s J2")


def _compose_hint(J1, J2, R1, R2):
    got = np.stack([J1, J2])
    truth = np.stack([R2.T, np.eye(3)])
    return _first_explained(
        got,
        [
            (np.stack([R2, np.eye(3)]), hints.COMPOSE_TRANSPOSE_HINT),
            (np.stack([np.eye(3), np.eye(3)]), hints.COMPOSE_IGNORES_R2_HINT),
            (np.stack([np.eye(3), R1]), hints.COMPOSE_LEFT_HINT),
            (np.stack([np.eye(3), R2.T]), hints.COMPOSE_SWAPPED_HINT),
            (np.stack([R1.T, np.eye(3)]), hints.COMPOSE_WRONG_FACTOR_HINT),
        ],
        truth,
    ) or (
        FLOAT32_HINT
        if single_precision_error(got, truth)
        else "J1 must satisfy R1 Exp(d) R2 ≈ (R1 R2) Exp(J1 d): compare it with finite differences at a generic R2"
    )


@exercise("jacobians_of_compose", weight=3)
def test_compose_jacobian_of_the_first_factor(student):
    """J1 satisfies R1 Exp(d) R2 = (R1 R2) Exp(J1 d) exactly (to 1e-12) for R2 at every angle from 1e-12 to π,
    and matches finite differences"""
    second_factors = list(random_rotations(2, 9104)) + _rotations_at_every_angle(9101)  # generic turns first
    for R1, R2 in zip(random_rotations(len(second_factors), 9100), second_factors):
        J1, J2 = _pair(student.jacobians_of_compose(R1, R2), "jacobians_of_compose(R1, R2)")
        expect_close(
            J1,
            R2.T,
            1e-12,
            f"J1 for R2 turned by {np.linalg.norm(_log(R2)):.3g} rad",
            lambda: _compose_hint(J1, J2, R1, R2),
        )
    for R1, R2 in zip(random_rotations(3, 9102), random_rotations(3, 9103)):
        J1, J2 = _pair(student.jacobians_of_compose(R1, R2), "jacobians_of_compose(R1, R2)")
        numeric = _central(lambda d: _log((R1 @ R2).T @ R1 @ _exp(d) @ R2), 3)
        expect_close(
            J1,
            numeric,
            1e-8,
            "J1 against finite differences of Log((R1 R2)ᵀ R1 Exp(d) R2)",
            lambda: _compose_hint(J1, J2, R1, R2),
        )


@exercise("jacobians_of_compose", weight=1)
def test_compose_jacobian_of_the_second_factor(student):
    """J2 satisfies R1 R2 Exp(d) = (R1 R2) Exp(J2 d) exactly (to 1e-12) for 6 pairs of rotations"""
    for R1, R2 in zip(random_rotations(6, 9110), random_rotations(6, 9111)):
        J1, J2 = _pair(student.jacobians_of_compose(R1, R2), "jacobians_of_compose(R1, R2)")
        expect_close(J2, np.eye(3), 1e-12, "J2", lambda: _compose_hint(J1, J2, R1, R2))


@exercise("jacobians_of_compose", weight=1)
def test_compose_accepts_lists(student):
    """gives the same pair for plain lists as for arrays"""
    R1, R2 = random_rotations(2, 9120)
    arrays = _pair(student.jacobians_of_compose(R1, R2), "jacobians_of_compose(R1, R2)")
    lists = _pair(student.jacobians_of_compose(R1.tolist(), R2.tolist()), "jacobians_of_compose with lists")
    for a, b, name in zip(arrays, lists, ("J1", "J2")):
        expect_close(b, a, 1e-12, f"{name} with lists, compared with arrays", hints.CONVERT_INPUTS_NP_ASARRAY_HINT)


# ---------------------------------------------------------------- jacobian_of_inverse
def _inverse_hint(J, R):
    return _first_explained(
        J,
        [
            (-R.T, hints.INVERSE_LEFT_HINT),
            (-np.eye(3), hints.INVERSE_NOT_MOVED_HINT),
            (R, hints.INVERSE_SIGN_HINT),
            (R.T, hints.INVERSE_TRANSPOSE_HINT),
            (
                np.eye(3),
                "J = I fits neither R = I nor this R: compare (R Exp(d))⁻¹ with R⁻¹ Exp(J d) for a small d along "
                "one axis, first at R = I, then at a generic R",
            ),
        ],
        -R,
    ) or (
        FLOAT32_HINT
        if single_precision_error(J, -R)
        else "J must satisfy (R Exp(d))⁻¹ ≈ R⁻¹ Exp(J d): compare it with finite differences, first at R = I"
    )


@exercise("jacobian_of_inverse", weight=3)
def test_inverse_jacobian_every_angle(student):
    """satisfies (R Exp(d))⁻¹ = R⁻¹ Exp(J d) exactly (to 1e-12) for rotations at every angle from 1e-12 to π"""
    for R in list(random_rotations(4, 9201)) + _rotations_at_every_angle(9200):  # generic turns first
        J = expect_array(student.jacobian_of_inverse(R), (3, 3), "jacobian_of_inverse(R)")
        expect_close(
            J,
            -R,
            1e-12,
            f"jacobian_of_inverse for a turn of {np.linalg.norm(_log(R)):.3g} rad",
            lambda: _inverse_hint(J, R),
        )


@exercise("jacobian_of_inverse", weight=1)
def test_inverse_jacobian_finite_differences(student):
    """matches central differences of Log(R (R Exp(d))⁻¹) to 1e-8 for 4 random rotations"""
    for R in random_rotations(4, 9210):
        J = expect_array(student.jacobian_of_inverse(R), (3, 3), "jacobian_of_inverse(R)")
        numeric = _central(lambda d: _log(R @ (R @ _exp(d)).T), 3)
        expect_close(J, numeric, 1e-8, "jacobian_of_inverse against finite differences", lambda: _inverse_hint(J, R))


@exercise("jacobian_of_inverse", weight=1)
def test_inverse_jacobian_at_the_identity(student):
    """is exact at the identity, where (Exp(d))⁻¹ = Exp(J d) for every small d"""
    J = expect_array(student.jacobian_of_inverse(np.eye(3)), (3, 3), "jacobian_of_inverse(I)")
    expect_close(J, -np.eye(3), 1e-15, "jacobian_of_inverse(I)", hints.INVERSE_AT_IDENTITY_HINT)


@exercise("jacobian_of_inverse", weight=1)
def test_inverse_jacobian_accepts_lists(student):
    """gives the same answer for plain lists as for arrays"""
    expect_same_with_lists(
        student.jacobian_of_inverse, (random_rotations(1, 9220)[0],), (3, 3), "jacobian_of_inverse(R)"
    )
