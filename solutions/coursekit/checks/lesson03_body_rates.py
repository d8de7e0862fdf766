"""Public checks for lesson 03, section 8: body and world angular velocity.

A body rolled a quarter turn about x (its y axis points up) spins at 1 rad/s about the world's vertical; its
attitude and the derivative of its attitude are written out by hand, and so are the values the usual slips
return for them (``tests/test_public_check_constants_lesson03_body_rates.py`` recomputes every one).
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import FLOAT32_HINT, close, float32_rounding
from ..lie import Exp
from .common import fmt, off_by, require_same_with_lists, require_shape

ROLLED = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])        # a quarter turn about x
ROLLED_DOT = np.array([[0.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])     # its derivative, spinning about world z
BODY_RATE = np.array([0.0, 1.0, 0.0])                                          # the spin about the body's own y
WORLD_RATE = np.array([0.0, 0.0, 1.0])
VEE_OF_R_DOT = np.array([0.0, 0.5, 0.5])          # the "vee" of Ṙ itself (not skew-symmetric)
TURNED_TWICE = np.array([0.0, 0.0, -1.0])         # Rᵀ applied to the body rate once more

WORLD_HINT = hints.BODY_RATE_IS_WORLD_RATE_HINT
SIGN_HINT = ("the opposite spin: ω_b came out negated; at R = I a body spinning positively about z has "
             "Ṙ = [e_z]× and must give +e_z")
IGNORES_R_HINT = ("Ṙ alone is not skew-symmetric: it still holds the attitude R, so what was read off it is not "
                  "a rate in the body's axes")
TWICE_HINT = hints.RATE_TURNED_INTO_BODY_HINT
SLIPS = [(WORLD_RATE, WORLD_HINT), (-BODY_RATE, SIGN_HINT), (VEE_OF_R_DOT, IGNORES_R_HINT),
         (TURNED_TWICE, TWICE_HINT), (-WORLD_RATE, WORLD_HINT)]


def _slip_hint(got, scale=1.0):
    for value, hint in SLIPS:
        if close(got, scale * value, 1e-9 * scale):
            return hint
    return None


@public_check("body_angular_velocity", "a body rolled a quarter turn about x, spinning about the world's vertical, "
                                       "spins about its own y")
def _(body_angular_velocity):
    got = require_shape(body_angular_velocity(ROLLED, ROLLED_DOT), (3,), "body_angular_velocity(R, Ṙ)")
    if not close(got, BODY_RATE, 1e-12):
        raise Mismatch(f"got {fmt(got)} rad/s, expected {fmt(BODY_RATE)} ({off_by(got, BODY_RATE)})",
                       _slip_hint(got) or "the body spins about the world's vertical, which is its own y axis after the "
                       "roll: ω_b must be written in the body's axes")


@public_check("body_angular_velocity", "keeps a tiny spin (1e-12 rad/s) to 1e-9 of its size, and doubles with Ṙ")
def _(body_angular_velocity):
    tiny = require_shape(body_angular_velocity(ROLLED, 1e-12 * ROLLED_DOT), (3,), "body_angular_velocity(R, 1e-12 Ṙ)")
    if not close(tiny, 1e-12 * BODY_RATE, 1e-21):
        raise Mismatch(f"for a spin of 1e-12 rad/s got {fmt(tiny / 1e-12)} × 1e-12 rad/s",
                       _slip_hint(tiny, 1e-12) or "nothing here needs a threshold: the formula is linear in Ṙ")
    double = require_shape(body_angular_velocity(ROLLED, 2.0 * ROLLED_DOT), (3,), "body_angular_velocity(R, 2 Ṙ)")
    single = require_shape(body_angular_velocity(ROLLED, ROLLED_DOT), (3,), "body_angular_velocity(R, Ṙ)")
    if not close(double, 2.0 * single, 1e-12):
        raise Mismatch("twice the rate of change does not give twice the angular velocity",
                       "ω_b is linear in Ṙ: no normalisation, no square roots")


# A generic attitude and body rate (every component non-zero and different), so that every entry of Ṙ counts.
GENERIC_R = Exp([0.4, -1.1, 0.7])
GENERIC_RATE = np.array([0.3, -0.5, 0.8])
# the derivative of the attitude of a body at GENERIC_R spinning at GENERIC_RATE about its own axes, written out
GENERIC_R_DOT = np.array([[-0.887075614259814, -0.42000061099320174, 0.07015297347667915],
                          [0.2699133299080473, -0.436273271174007, -0.37388829319927214],
                          [0.17390701228968208, -0.6027147912773244, -0.44191187415695854]])


@public_check("body_angular_velocity", "recovers a generic body rate (0.3, -0.5, 0.8) rad/s at a generic attitude, "
                                       "to 1e-12")
def _(body_angular_velocity):
    got = require_shape(body_angular_velocity(GENERIC_R.copy(), GENERIC_R_DOT.copy()), (3,),
                        "body_angular_velocity(R, Ṙ)")
    if not close(got, GENERIC_RATE, 1e-12):
        raise Mismatch(f"got {fmt(got, 6)} rad/s, expected {fmt(GENERIC_RATE)} ({off_by(got, GENERIC_RATE)})",
                       FLOAT32_HINT if float32_rounding(got, GENERIC_RATE) else
                       "ω_b is wrong at a generic attitude: R(t) = Exp(t R0 ω_b) R0 spins at ω_b in body axes "
                       "(at R0 ω_b in world axes), so its derivative at t = 0 is a test whose answer you know; "
                       "compare each component")


@public_check("body_angular_velocity", "accepts plain lists")
def _(body_angular_velocity):
    require_same_with_lists(body_angular_velocity, (ROLLED, ROLLED_DOT), (3,), "body_angular_velocity(R, Ṙ)")
