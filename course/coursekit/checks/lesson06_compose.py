"""Public checks for lesson 06, section 10: the Jacobians of composition and inversion.

The checks use quarter turns written out by hand, finite differences of each Jacobian's definition (central
differences, computed here with the library's Exp and Log), the identity, and the fact that both Jacobians keep
the size of a small turn. The usual slips are recognised by what would pass instead (the transpose, the left
version, the definition at other inputs), never by their formulas (``tests/test_public_check_constants_lesson06_compose.py``
checks the hand-written turns against scipy).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import FLOAT32_HINT, close, single_precision_error
from ..lie import Exp, Log
from .common import central_differences, off_by, require_same_with_lists, require_shape, require_unchanged_inputs

# Quarter turns, written out: about z (x goes to y), about x (y goes to z), and their product (a third of
# a turn about (1, 1, 1), which permutes the axes x → y → z → x).
QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
QUARTER_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
PERMUTATION = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])   # QUARTER_Z @ QUARTER_X


def _require_turn_preserving(J, what, why):
    """Mismatch unless Jᵀ J = I to 1e-12 at generic rotations (float64 stays near 1e-16, float32 near 1e-7)."""
    error = float(np.max(np.abs(J.T @ J - np.eye(3))))
    if error > 1e-12:
        raise Mismatch(f"{what}ᵀ {what} is off from I by {error:.2g} for generic rotations (allowed 1e-12): {why}",
                       FLOAT32_HINT if single_precision_error(J.T @ J, np.eye(3)) else None)


# ---------------------------------------------------------------- jacobians_of_compose
def _compose_numeric(R1, R2, left=False):
    """(J1, J2) by central differences of their definitions: R1 Exp(d) R2 = R1 R2 Exp(J1 d) and
    R1 R2 Exp(d) = R1 R2 Exp(J2 d); with ``left``, of the left versions Exp(J1 d) R1 R2 = Exp(d) R1 R2 and
    Exp(J2 d) R1 R2 = R1 Exp(d) R2."""
    R = R1 @ R2
    if left:
        return (central_differences(lambda d: Log(Exp(d) @ R @ R.T), 3),
                central_differences(lambda d: Log(R1 @ Exp(d) @ R2 @ R.T), 3))
    return (central_differences(lambda d: Log(R.T @ R1 @ Exp(d) @ R2), 3),
            central_differences(lambda d: Log(R.T @ R @ Exp(d)), 3))


def _compose_hint(jacobians_of_compose, J1, J2, R1, R2):
    """Name the slip by what would pass: Jᵀ for J, the two swapped, the left versions, J1 of R2 R1, or a J1 that
    ignores R2 (the student's own J1 at R2 = I, where it is right)."""
    def same(pair, other):
        return close(pair[0], other[0], 1e-6) and close(pair[1], other[1], 1e-6)

    truth = _compose_numeric(R1, R2)
    if same((J1.T, J2), truth):
        return hints.COMPOSE_TRANSPOSE_HINT
    if close(J1, _compose_numeric(R1, np.eye(3))[0], 1e-6) and close(J2, truth[1], 1e-6):
        try:
            at_identity = _pair(jacobians_of_compose(R1, np.eye(3)), "jacobians_of_compose(R1, I)")[0]
        except Mismatch:
            at_identity = None
        if at_identity is not None and close(at_identity, J1, 1e-9):
            return hints.COMPOSE_IGNORES_R2_HINT
    if same((J1, J2), _compose_numeric(R1, R2, left=True)):
        return hints.COMPOSE_LEFT_HINT
    if same((J2, J1), truth):
        return hints.COMPOSE_SWAPPED_HINT
    if close(J1, _compose_numeric(R2, R1)[0], 1e-6):
        return hints.COMPOSE_WRONG_FACTOR_HINT
    return None


def _pair(value, what):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(f"{what} returned {type(value).__name__}, not a pair (J1, J2)",
                       "return two 3×3 arrays: return J1, J2")
    return (require_shape(value[0], (3, 3), f"{what}'s J1"), require_shape(value[1], (3, 3), f"{what}'s J2"))


@public_check("jacobians_of_compose", "J1 and J2 match finite differences of Log((R1 R2)ᵀ R1 Exp(d) R2) and of "
                                      "Log((R1 R2)ᵀ R1 R2 Exp(d))")
def _(jacobians_of_compose):
    R1, R2 = QUARTER_Z, QUARTER_X   # quarter turns about z and x
    J1, J2 = _pair(jacobians_of_compose(R1, R2), "jacobians_of_compose(R1, R2)")
    numeric1 = central_differences(lambda d: Log((R1 @ R2).T @ R1 @ Exp(d) @ R2), 3)
    numeric2 = central_differences(lambda d: Log((R1 @ R2).T @ R1 @ R2 @ Exp(d)), 3)
    if close(J1, numeric1, 1e-6) and close(J2, numeric2, 1e-6):
        return
    hint = _compose_hint(jacobians_of_compose, J1, J2, R1, R2)
    which = "J1" if not close(J1, numeric1, 1e-6) else "J2"
    error = off_by(J1, numeric1) if which == "J1" else off_by(J2, numeric2)
    raise Mismatch(f"{which} disagrees with finite differences ({error})",
                   hint or "write R1 Exp(d) R2 as (R1 R2) Exp(J1 d), and R1 R2 Exp(d) likewise, then read off J1 and J2")


@public_check("jacobians_of_compose", "accepts plain lists and leaves its inputs unchanged")
def _(jacobians_of_compose):
    R1, R2 = Exp([0.3, -0.5, 0.2]), Exp([-0.4, 0.1, 0.9])
    arrays = _pair(jacobians_of_compose(R1.copy(), R2.copy()), "jacobians_of_compose(R1, R2)")
    try:
        lists = _pair(jacobians_of_compose(R1.tolist(), R2.tolist()), "jacobians_of_compose with lists")
    except Mismatch:
        raise
    except Exception as error:
        raise Mismatch(f"jacobians_of_compose with lists raised {type(error).__name__}: {error}",
                       hints.CONVERT_INPUTS_NP_ASARRAY_HINT) from None
    if not (close(arrays[0], lists[0], 1e-12) and close(arrays[1], lists[1], 1e-12)):
        raise Mismatch("jacobians_of_compose with lists differs from arrays",
                       hints.CONVERT_INPUTS_NP_ASARRAY_HINT)
    require_unchanged_inputs(jacobians_of_compose, (R1, R2), "jacobians_of_compose")


@public_check("jacobians_of_compose", "for generic rotations, J1 and J2 keep a small turn's size, to 1e-12")
def _(jacobians_of_compose):
    J1, J2 = _pair(jacobians_of_compose(Exp([0.3, -0.5, 0.2]), Exp([-0.4, 0.1, 0.9])), "jacobians_of_compose(R1, R2)")
    _require_turn_preserving(J1, "J1", "a small turn must keep its angle")
    _require_turn_preserving(J2, "J2", "a small turn must keep its angle")


# ---------------------------------------------------------------- jacobian_of_inverse
def _inverse_numeric(R, left=False):
    """J by central differences of (R Exp(d))⁻¹ = R⁻¹ Exp(J d); with ``left``, of (Exp(d) R)⁻¹ = Exp(J d) R⁻¹."""
    if left:
        return central_differences(lambda d: Log((Exp(d) @ R).T @ R), 3)
    return central_differences(lambda d: Log(R @ (R @ Exp(d)).T), 3)


def _inverse_hint(jacobian_of_inverse, J, R):
    """Name the slip by what would pass: the left version, J at the identity (and the student's J there is the
    same), -J, or -Jᵀ."""
    for candidate, expected, hint in [(J, _inverse_numeric(R, left=True), hints.INVERSE_LEFT_HINT),
                                      (-J, _inverse_numeric(R), hints.INVERSE_SIGN_HINT),
                                      (-J.T, _inverse_numeric(R), hints.INVERSE_TRANSPOSE_HINT)]:
        if close(candidate, expected, 1e-6):
            return hint
    if close(J, _inverse_numeric(np.eye(3)), 1e-6):
        at_identity = require_shape(jacobian_of_inverse(np.eye(3)), (3, 3), "jacobian_of_inverse(I)")
        if close(at_identity, J, 1e-9):
            return hints.INVERSE_NOT_MOVED_HINT
    return None


@public_check("jacobian_of_inverse", "matches finite differences of Log(R (R Exp(d))⁻¹), for a third of a turn "
                                     "about (1, 1, 1)")
def _(jacobian_of_inverse):
    R = PERMUTATION
    J = require_shape(jacobian_of_inverse(R), (3, 3), "jacobian_of_inverse(R)")
    numeric = central_differences(lambda d: Log(R @ (R @ Exp(d)).T), 3)
    if not close(J, numeric, 1e-6):
        hint = _inverse_hint(jacobian_of_inverse, J, R)
        raise Mismatch(f"disagrees with finite differences ({off_by(J, numeric)})",
                       hint or "write (R Exp(d))⁻¹ as R⁻¹ Exp(J d) and read off J")


@public_check("jacobian_of_inverse", "is exact at the identity (to 1e-12), accepts lists, leaves R unchanged")
def _(jacobian_of_inverse):
    J = require_shape(jacobian_of_inverse(np.eye(3)), (3, 3), "jacobian_of_inverse(I)")
    exact = central_differences(lambda d: Log(Exp(d).T), 3, h=0.1)
    if not close(J, exact, 1e-12):
        raise Mismatch(f"jacobian_of_inverse(I) disagrees with inverting Exp(d) ({off_by(J, exact)})",
                       hints.INVERSE_AT_IDENTITY_HINT)
    require_same_with_lists(jacobian_of_inverse, (PERMUTATION,), (3, 3), "jacobian_of_inverse(R)")
    require_unchanged_inputs(jacobian_of_inverse, (PERMUTATION,), "jacobian_of_inverse")


@public_check("jacobian_of_inverse", "for a generic rotation, J keeps a small turn's size, to 1e-12")
def _(jacobian_of_inverse):
    J = require_shape(jacobian_of_inverse(Exp([0.3, -0.5, 0.2])), (3, 3), "jacobian_of_inverse(R)")
    _require_turn_preserving(J, "J", "inverting must keep a small turn's angle")
