"""Public checks for lesson 03: the Lie algebra so(3), exp and log.

The checks use rotations whose axis and angle are known by construction —
quarter and half turns written out entry by entry, a tiny turn about z built
from cos and sin, scipy's rotation through ``coursekit.lie.Exp`` — and defining properties: hat(w) @ v is the cross product,
exp of a rotation vector fixes its axis, log undoes exp.
"""

import numpy as np

from ..checking import Mismatch, public_check
from ..diagnose import close, rotation_problem, rotation_vector_hint
from ..lie import Exp
from .common import fmt, off_by, require_same_with_lists, require_shape

QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
HALF_TURN_Z = np.diag([-1.0, -1.0, 1.0])
DIAGONAL = np.ones(3) / np.sqrt(3.0)
HALF_TURN_DIAGONAL = 2.0 * np.outer(DIAGONAL, DIAGONAL) - np.eye(3)   # π about (1, 1, 1)/√3
W_SAMPLE = np.array([0.3, -1.2, 0.5])
V_SAMPLE = np.array([2.0, 0.1, -0.7])
SKEW_SAMPLE = np.array([[0.0, -0.5, -1.2], [0.5, 0.0, -0.3], [1.2, 0.3, 0.0]])   # hat of (0.3, -1.2, 0.5)


def _rot_z(angle):
    return Exp([0.0, 0.0, angle])


# ---------------------------------------------------------------- hat, vee
@public_check("hat", "hat(w) @ v equals the cross product w × v")
def _(hat):
    W = require_shape(hat(W_SAMPLE), (3, 3))
    got, want = W @ V_SAMPLE, np.cross(W_SAMPLE, V_SAMPLE)
    if close(got, -want, 1e-12):
        raise Mismatch(f"hat(w) @ v = {fmt(got)} is -(w × v)",
                       "the signs are swapped (the transpose): the top row is [0, -w3, w2]")
    if not close(got, want, 1e-12):
        raise Mismatch(f"hat(w) @ v = {fmt(got)}, but w × v = {fmt(want)}")


@public_check("hat", "returns a skew-symmetric matrix (Wᵀ = -W)")
def _(hat):
    W = require_shape(hat(W_SAMPLE), (3, 3))
    if not close(W, -W.T, 1e-15):
        raise Mismatch("hat(w) + hat(w)ᵀ is not zero", "the diagonal is zero and W[j, i] = -W[i, j]")


@public_check("vee", "vee undoes hat: vee([w]×) = w")
def _(vee):
    got = require_shape(vee(SKEW_SAMPLE), (3,))
    if close(got, -W_SAMPLE, 1e-12):
        raise Mismatch(f"vee returned {fmt(got)}, the negative of w = {fmt(W_SAMPLE)}",
                       "read w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0] (the entries with a plus sign)")
    if not close(got, W_SAMPLE, 1e-12):
        raise Mismatch(f"vee returned {fmt(got)}, expected {fmt(W_SAMPLE)}")


@public_check("vee", "accepts a nested list")
def _(vee):
    require_same_with_lists(vee, (SKEW_SAMPLE,), (3,), "vee")


# ---------------------------------------------------------------- bracket
@public_check("bracket", "[e_x^, e_y^] = e_z^ (the cross product e_x × e_y = e_z)")
def _(bracket):
    X = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    Y = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])
    Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    got = require_shape(bracket(X, Y), (3, 3))
    if close(got, Z, 1e-12):
        return
    if close(got, np.zeros((3, 3)), 1e-12):
        raise Mismatch("bracket returned the zero matrix", "use @ (matrix product), not * (entry by entry)")
    if close(got, -Z, 1e-12):
        raise Mismatch("got -[e_z]×", "the order is AB - BA, not BA - AB")
    if close(got, X @ Y + Y @ X, 1e-12):
        raise Mismatch("got AB + BA", "the bracket is the difference AB - BA")
    raise Mismatch(f"bracket(X, Y) =\n{got}\nexpected [e_z]×")


@public_check("bracket", "works for square matrices of any size (2×2)")
def _(bracket):
    A = np.array([[1.0, 2.0], [0.0, -1.0]])
    B = np.array([[0.0, 1.0], [3.0, 0.5]])
    got = require_shape(bracket(A, B), (2, 2))
    if not close(got, A @ B - B @ A, 1e-12):
        raise Mismatch(f"bracket of two 2×2 matrices returned {fmt(got)}")


# ---------------------------------------------------------------- exp_series
@public_check("exp_series", "n_terms = 1, 2, 3 give I, I + W, I + W + W²/2")
def _(exp_series):
    W = SKEW_SAMPLE
    partial = [np.eye(3), np.eye(3) + W, np.eye(3) + W + W @ W / 2]
    for n, expected in zip((1, 2, 3), partial):
        got = require_shape(exp_series(W, n), (3, 3))
        if close(got, expected, 1e-12):
            continue
        if n == 1 and close(got, np.zeros((3, 3)), 1e-12):
            raise Mismatch("exp_series(W, 1) is the zero matrix", "the first term (k = 0) is the identity")
        if n == 1 and close(got, W, 1e-12):
            raise Mismatch("exp_series(W, 1) is W", "start at k = 0: the first term is W⁰ = I")
        if n < 3 and close(got, partial[n], 1e-12):
            raise Mismatch(f"exp_series(W, {n}) already includes the term k = {n}",
                           "one term too many: n_terms terms means k = 0 … n_terms - 1")
        raise Mismatch(f"exp_series(W, {n}) differs from the sum of its first {n} terms")


@public_check("exp_series", "many terms sum to a rotation: the quarter turn about z")
def _(exp_series):
    W = np.array([[0.0, -np.pi / 2, 0.0], [np.pi / 2, 0.0, 0.0], [0.0, 0.0, 0.0]])
    got = require_shape(exp_series(W, 30), (3, 3))
    if not close(got, QUARTER_TURN_Z, 1e-12):
        hint = "W ** k raises entries to a power; use term = term @ W / k" \
            if close(got[2, 2], 1.0, 1e-9) and not close(got[0, 0], 0.0, 1e-3) else None
        raise Mismatch(f"30 terms of exp([π/2 e_z]×) give x → {fmt(got[:, 0])}, expected [0, 1, 0]", hint)


# ---------------------------------------------------------------- exp_so3
@public_check("exp_so3", "a quarter turn about z sends x to y")
def _(exp_so3):
    R = require_shape(exp_so3([0.0, 0.0, np.pi / 2]), (3, 3))
    if close(R, QUARTER_TURN_Z.T, 1e-9):
        raise Mismatch("got the inverse rotation (x → -y)", "check the sign of the sin θ term: R = I + sin θ K + ...")
    if not close(R, QUARTER_TURN_Z, 1e-12):
        raise Mismatch(f"exp_so3([0, 0, π/2]) sends x to {fmt(R[:, 0])}, expected [0, 1, 0]")


@public_check("exp_so3", "returns a rotation that leaves its axis fixed")
def _(exp_so3):
    R = require_shape(exp_so3(W_SAMPLE), (3, 3))
    problem = rotation_problem(R, 1e-12)
    if problem:
        raise Mismatch(f"exp_so3(w) is not a rotation: {problem}")
    if not close(R @ W_SAMPLE, W_SAMPLE, 1e-12):
        raise Mismatch("exp_so3(w) moves its own axis w")


@public_check("exp_so3", "w = 0 gives I, and a tiny turn (1e-8 rad) is not lost")
def _(exp_so3):
    got = require_shape(exp_so3([0.0, 0.0, 0.0]), (3, 3))
    if not close(got, np.eye(3), 1e-15):
        raise Mismatch("exp_so3(0) is not the identity", "at θ = 0 use the limits sin θ/θ → 1, (1 - cos θ)/θ² → 1/2")
    got = require_shape(exp_so3([0.0, 0.0, 1e-8]), (3, 3))
    if close(got, np.eye(3), 1e-12):
        raise Mismatch("exp_so3([0, 0, 1e-8]) returned exactly I: the turn of 1e-8 rad was dropped",
                       "for small θ use the Taylor coefficients, never return I")
    if not close(got, _rot_z(1e-8), 1e-15):
        raise Mismatch(f"exp_so3([0, 0, 1e-8]) is {off_by(got, _rot_z(1e-8))} (R[1, 0] = {got[1, 0]:.3g}, "
                       "expected 1e-08)")


# ---------------------------------------------------------------- log_so3
@public_check("log_so3", "undoes a quarter turn about z: [0, 0, π/2]")
def _(log_so3):
    got = require_shape(log_so3(QUARTER_TURN_Z), (3,))
    want = np.array([0.0, 0.0, np.pi / 2])
    if not close(got, want, 1e-12):
        raise Mismatch(f"log_so3 of the quarter turn is {off_by(got, want)}: returned {fmt(got)}",
                       rotation_vector_hint(got, want))


@public_check("log_so3", "the identity gives 0, and tiny turns keep their relative accuracy")
def _(log_so3):
    got = require_shape(log_so3(np.eye(3)), (3,), "log_so3(I)", lambda got: rotation_vector_hint(got, np.zeros(3)))
    if not close(got, np.zeros(3), 1e-15):
        raise Mismatch(f"log_so3(I) returned {fmt(got)}", rotation_vector_hint(got, np.zeros(3)))
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    for angle in (1e-8, 1e-3):
        want = angle * axis
        got = require_shape(log_so3(Exp(want)), (3,), f"log_so3 at θ = {angle:g}",
                            lambda got: rotation_vector_hint(got, want))
        if not close(got, want, 1e-15 + 1e-10 * angle):
            raise Mismatch(f"log_so3 of a {angle:g} rad turn is {off_by(got, want)} "
                           f"(relative {np.max(np.abs(got - want)) / angle:.2g}): returned {got}",
                           rotation_vector_hint(got, want)
                           or "keep θ/sin θ (≈ 1 + θ²/6 for small θ): dropping the θ² term shows at θ = 1e-3")


@public_check("log_so3", "exact at θ = π, also about (1, 1, 1)/√3 (either sign)")
def _(log_so3):
    for name, R, axis in [("the half turn about z", HALF_TURN_Z, np.array([0.0, 0.0, 1.0])),
                          ("the half turn about (1, 1, 1)/√3", HALF_TURN_DIAGONAL, DIAGONAL)]:
        got = require_shape(log_so3(R), (3,))
        want = np.pi * axis
        if not (close(got, want, 1e-10) or close(got, -want, 1e-10)):
            error = min(np.max(np.abs(got - want)), np.max(np.abs(got + want)))
            raise Mismatch(f"log_so3 of {name} is off by {error:.2g} (either sign accepted): returned {fmt(got)}",
                           rotation_vector_hint(got, want))


@public_check("log_so3", "just below π the sign of the axis is right")
def _(log_so3):
    angle = np.pi - 1e-6
    axis = np.array([0.0, -0.6, -0.8])            # its largest component is negative
    R = Exp(angle * axis)
    got = require_shape(log_so3(R), (3,))
    want = angle * axis
    if not close(got, want, 1e-8):
        raise Mismatch(f"log_so3 is {off_by(got, want)} at θ = π - 1e-6 about {fmt(axis)}: returned {fmt(got)}",
                       rotation_vector_hint(got, want))


# ---------------------------------------------------------------- axis_angle
def _pair(value):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(f"returned {type(value).__name__}, expected a pair (u, theta)", "return u, theta")
    u = require_shape(value[0], (3,))
    theta = require_shape(value[1], ())
    return u, float(theta)


@public_check("axis_angle", "a quarter turn about z: u = [0, 0, 1], θ = π/2")
def _(axis_angle):
    u, theta = _pair(axis_angle(QUARTER_TURN_Z))
    if close(theta, 90.0, 1e-6):
        raise Mismatch("θ = 90", "the angle must be in radians")
    if not (close(u, [0.0, 0.0, 1.0], 1e-12) and close(theta, np.pi / 2, 1e-12)):
        raise Mismatch(f"got u = {fmt(u)}, θ = {theta:.6g}; expected u = [0, 0, 1], θ = π/2")


@public_check("axis_angle", "the identity: θ = 0 with a unit axis (no NaN)")
def _(axis_angle):
    u, theta = _pair(axis_angle(np.eye(3)))
    if not (close(theta, 0.0, 1e-15) and close(np.linalg.norm(u), 1.0, 1e-12)):
        raise Mismatch(f"got u = {fmt(u)}, θ = {theta:.3g}",
                       "at θ = 0 the axis is arbitrary: return the unit vector [1, 0, 0]")


@public_check("axis_angle", "a half turn about (1, 1, 1)/√3: θ = π, u = ±(1, 1, 1)/√3")
def _(axis_angle):
    u, theta = _pair(axis_angle(HALF_TURN_DIAGONAL))
    if not close(theta, np.pi, 1e-12) or not (close(u, DIAGONAL, 1e-10) or close(u, -DIAGONAL, 1e-10)):
        raise Mismatch(f"got u = {fmt(u)}, θ = {theta:.6g}",
                       "near π take the axis from the symmetric part (R + Rᵀ)/2")


# ---------------------------------------------------------------- axis_from_eigen
def _real(value):
    """A real (3,) vector; a complex one is accepted when its imaginary part is zero (as np.linalg.eig gives)."""
    array = np.asarray(value) if value is not None else None
    if array is not None and np.iscomplexobj(array):
        if array.shape == (3,) and np.max(np.abs(array.imag)) > 1e-12:
            raise Mismatch(f"returned a complex vector with imaginary part {fmt(np.abs(array.imag))}",
                           "take the eigenvector of the eigenvalue 1: it is real (np.real(...) of it)")
        value = array.real
    return require_shape(value, (3,))


@public_check("axis_from_eigen", "returns a real unit vector with R u = u")
def _(axis_from_eigen):
    angle = 2.0
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    R = Exp(angle * axis)
    u = _real(axis_from_eigen(R))
    if not close(np.linalg.norm(u), 1.0, 1e-12):
        raise Mismatch(f"|u| = {np.linalg.norm(u):.6g}", "normalise the eigenvector")
    if not close(R @ u, u, 1e-10):
        raise Mismatch(f"R u ≠ u for u = {fmt(u)}",
                       "eigenvectors are the columns vectors[:, k], for the eigenvalue closest to 1")


@public_check("axis_from_eigen", "a half turn about z: u = ±e_z")
def _(axis_from_eigen):
    u = _real(axis_from_eigen(HALF_TURN_Z))
    if not (close(u, [0.0, 0.0, 1.0], 1e-12) or close(u, [0.0, 0.0, -1.0], 1e-12)):
        raise Mismatch(f"got {fmt(u)}", "pick the eigenvalue closest to 1 (the others are -1 here)")
