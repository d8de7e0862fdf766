"""Public checks for lesson 06, section 9: a world point seen from the body.

The Jacobian is compared with central differences of (R Exp(δ))ᵀ p_w taken here (scipy's Exp), at a quarter turn
about z and p_w = (1, 2, -0.5). The usual slips are recognised by what the finite differences of another map give
instead (the left perturbation, the body-to-world map, the same map at R = I, or the negative), never by stored
values (``tests/test_public_check_constants_lesson06_point_to_body.py`` gives each slip to them).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import close
from ..lie import Exp
from .common import off_by, require_same_with_lists, require_shape

QUARTER_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
P_WORLD = np.array([1.0, 2.0, -0.5])
LEFT_HINT = hints.LEFT_PERTURBATION_POINT_JACOBIAN_HINT
SIGN_HINT = hints.POINT_TO_BODY_SIGN_HINT
NO_R_HINT = hints.POINT_SEEN_BODY_RT_HINT
FORWARD_HINT = ("that is Exercise 5's answer, which is the Jacobian of R p (body to world); here the map is Rᵀ p_w "
                "(world to body), and the perturbation sits inside a transpose")


def _central(f, h=1e-6):
    return np.column_stack([(f(h * e) - f(-h * e)) / (2 * h) for e in np.eye(3)])


def _slip_hint(J, R, p_w):
    """Name the slip by what would pass instead: the finite differences of the left perturbation (Exp(δ) R)ᵀ p_w,
    of the body-to-world map R Exp(δ) p_w, of the right map at R = I, or minus those of the right map here."""
    numeric = _central(lambda d: (R @ Exp(d)).T @ p_w)
    for candidate, expected, hint in [(J, _central(lambda d: (Exp(d) @ R).T @ p_w), LEFT_HINT),
                                      (J, _central(lambda d: R @ Exp(d) @ p_w), FORWARD_HINT),
                                      (J, _central(lambda d: Exp(d).T @ p_w), NO_R_HINT),
                                      (-J, numeric, SIGN_HINT)]:
        if close(candidate, expected, 1e-8):
            return hint
    return None


@public_check("jacobian_point_to_body", "matches finite differences of (R Exp(δ))ᵀ p_w (quarter turn about z)")
def _(jacobian_point_to_body):
    J = require_shape(jacobian_point_to_body(QUARTER_Z, P_WORLD), (3, 3), "jacobian_point_to_body(R, p_w)")
    numeric = _central(lambda d: (QUARTER_Z @ Exp(d)).T @ P_WORLD)
    if not close(J, numeric, 1e-8):
        raise Mismatch(f"disagrees with finite differences ({off_by(J, numeric)})",
                       _slip_hint(J, QUARTER_Z, P_WORLD) or
                       "J must match the finite differences column by column: column j is how the body-frame point "
                       "moves per radian of turn about the body's axis j")


@public_check("jacobian_point_to_body", "a turn about the point's own body-frame direction does not move it")
def _(jacobian_point_to_body):
    R = Exp([0.4, -0.9, 0.3])
    p_w = np.array([0.3, 1.7, -2.1])          # not exact in float32: a float32 copy of it shows
    J = require_shape(jacobian_point_to_body(R, p_w), (3, 3), "jacobian_point_to_body(R, p_w)")
    moved = J @ (R.T @ p_w)
    if np.max(np.abs(moved)) > 1e-12:
        raise Mismatch(f"a turn about the direction of Rᵀ p_w moves the point by {np.max(np.abs(moved)):.2g} m/rad",
                       "turning about the line of sight leaves the point on it: J (Rᵀ p_w) must be 0")


@public_check("jacobian_point_to_body", "accepts plain lists")
def _(jacobian_point_to_body):
    require_same_with_lists(jacobian_point_to_body, (QUARTER_Z, P_WORLD), (3, 3), "jacobian_point_to_body(R, p_w)")
