"""Public checks for lesson 03: the Lie algebra so(3), exp and log.

The checks use rotations whose axis and angle are known by construction —
quarter and half turns written out entry by entry, a tiny turn about z built
from cos and sin, scipy's rotation through ``coursekit.lie.Exp`` — and defining properties: hat(w) @ v is the cross product,
exp of a rotation vector fixes its axis, log undoes exp.
"""

import numpy as np

from ..checking import Mismatch, public_check
from ..diagnose import close, rotation_problem
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


def _explains(got, candidate, truth):
    """True when ``candidate`` (what a known slip returns) accounts for ``got``'s error from ``truth``."""
    got, candidate, truth = (np.asarray(x, dtype=float) for x in (got, candidate, truth))
    if got.shape != candidate.shape or not np.all(np.isfinite(candidate)):
        return False
    gap = float(np.max(np.abs(candidate - truth)))
    return gap > 0.0 and float(np.max(np.abs(got - candidate))) <= 1e-3 * gap + 1e-15


def _skew(w):
    x, y, z = np.asarray(w, dtype=float)
    return np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])


# ---------------------------------------------------------------- hat, vee
def _hat_hint(W, w):
    x, y, z = np.asarray(w, dtype=float)
    truth = _skew(w)
    if _explains(W, truth.T, truth):
        return "the signs are swapped (the transpose, -[w]×): the top row is [0, -w3, w2]"
    if _explains(W, np.array([[0.0, z, y], [z, 0.0, x], [y, x, 0.0]]), truth):
        return "the minus signs are missing (a symmetric matrix): [w]× = [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]]"
    if _explains(W, np.diag([x, y, z]), truth):
        return "w sits on the diagonal: [w]× has zeros there and w in the off-diagonal entries"
    for order in ((2, 1, 0), (1, 0, 2), (0, 2, 1), (1, 2, 0), (2, 0, 1)):
        if _explains(W, _skew(np.array([x, y, z])[list(order)]), truth):
            return "the components of w are permuted: W[2, 1] = w1, W[0, 2] = w2, W[1, 0] = w3"
    return "compare entry by entry with [[0, -w3, w2], [w3, 0, -w1], [-w2, w1, 0]]"


@public_check("hat", "hat(w) @ v equals the cross product w × v")
def _(hat):
    W = require_shape(hat(W_SAMPLE), (3, 3))
    got, want = W @ V_SAMPLE, np.cross(W_SAMPLE, V_SAMPLE)
    if not close(got, want, 1e-12):
        raise Mismatch(f"hat(w) @ v = {fmt(got)}, but w × v = {fmt(want)} ({off_by(got, want)})", _hat_hint(W, W_SAMPLE))


@public_check("hat", "returns a skew-symmetric matrix (Wᵀ = -W)")
def _(hat):
    W = require_shape(hat(W_SAMPLE), (3, 3))
    if not close(W, -W.T, 1e-15):
        raise Mismatch(f"hat(w) + hat(w)ᵀ is not zero (its largest entry is {np.max(np.abs(W + W.T)):.2g})",
                       "the diagonal is zero and W[j, i] = -W[i, j]")


def _vee_hint(got, W, w):
    if _explains(got, -w, w):
        return "the negative of w: read w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0] (the entries with a plus sign)"
    if _explains(got, np.array([W[0, 1], W[0, 2], W[1, 2]]), w):
        return ("read the entries above the diagonal in row order (W[0, 1], W[0, 2], W[1, 2] = -w3, w2, -w1): "
                "w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0]")
    if _explains(got, 2.0 * w, w):
        return "twice w: W - Wᵀ = 2[w]×, so take half of it (or read the entries of W directly)"
    if _explains(got, np.diag(W), w):
        return "returned the diagonal of W, which is zero: w sits off the diagonal (w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0])"
    return "vee reads w1 = W[2, 1], w2 = W[0, 2], w3 = W[1, 0]"


@public_check("vee", "vee undoes hat: vee([w]×) = w")
def _(vee):
    got = require_shape(vee(SKEW_SAMPLE), (3,))
    if not close(got, W_SAMPLE, 1e-12):
        raise Mismatch(f"vee returned {fmt(got)}, expected {fmt(W_SAMPLE)} ({off_by(got, W_SAMPLE)})",
                       _vee_hint(got, SKEW_SAMPLE, W_SAMPLE))


@public_check("vee", "accepts a nested list")
def _(vee):
    require_same_with_lists(vee, (SKEW_SAMPLE,), (3,), "vee")


# ---------------------------------------------------------------- bracket
def _bracket_hint(got, A, B):
    truth = A @ B - B @ A
    if _explains(got, A @ B + B @ A, truth):
        return "that is AB + BA: the bracket is the difference AB - BA"
    if _explains(got, B @ A - A @ B, truth):
        return "the order is AB - BA, not BA - AB"
    if _explains(got, A * B - B * A, truth):
        return "got zero: * multiplies entry by entry (A * B = B * A), use @ for the matrix product"
    if _explains(got, A @ B, truth):
        return "that is only AB: the bracket subtracts BA, [A, B] = AB - BA"
    if _explains(got, B @ A, truth):
        return "that is only BA: the bracket is AB - BA"
    return "[A, B] = A @ B - B @ A, with matrix products"


@public_check("bracket", "[e_x^, e_y^] = e_z^ (the cross product e_x × e_y = e_z)")
def _(bracket):
    X = np.array([[0.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
    Y = np.array([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0], [-1.0, 0.0, 0.0]])
    Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    got = require_shape(bracket(X, Y), (3, 3))
    if not close(got, Z, 1e-12):
        raise Mismatch(f"bracket(X, Y) =\n{got}\nexpected [e_z]× ({off_by(got, Z)})", _bracket_hint(got, X, Y))


@public_check("bracket", "works for square matrices of any size (2×2)")
def _(bracket):
    A = np.array([[1.0, 2.0], [0.0, -1.0]])
    B = np.array([[0.0, 1.0], [3.0, 0.5]])
    got = require_shape(bracket(A, B), (2, 2))
    if not close(got, A @ B - B @ A, 1e-12):
        raise Mismatch(f"bracket of two 2×2 matrices returned {fmt(got)} ({off_by(got, A @ B - B @ A)})",
                       _bracket_hint(got, A, B))


# ---------------------------------------------------------------- exp_series
def _partial(W, first, last, factorial=True):
    term, total = np.eye(len(W)), np.zeros_like(W)
    for k in range(last + 1):
        if k >= first:
            total = total + term
        term = term @ W / (k + 1 if factorial else 1)
    return total


def _series_hint(got, W, n):
    truth = _partial(W, 0, n - 1)
    if _explains(got, _partial(W, 1, n), truth) or _explains(got, _partial(W, 1, n - 1), truth):
        return "the identity term is missing: the sum starts at k = 0 (W⁰ = I)"
    if _explains(got, _partial(W, 0, n), truth):
        return "one term too many: n_terms terms means k = 0 … n_terms - 1"
    if n >= 2 and _explains(got, _partial(W, 0, n - 2), truth):
        return "one term too few: n_terms terms means k = 0 … n_terms - 1"
    if _explains(got, sum(W ** k / np.prod(np.arange(1, k + 1)) for k in range(n)), truth):
        return "W ** k is an entry-wise power: use the matrix product (term = term @ W / k)"
    if _explains(got, _partial(W, 0, n - 1, factorial=False), truth):
        return "the 1/k! is missing: the terms are W^k / k! (term = term @ W / k)"
    return "sum the terms W^k / k! for k = 0 … n_terms - 1, with matrix products"


@public_check("exp_series", "n_terms = 1, 2, 3 give I, I + W, I + W + W²/2")
def _(exp_series):
    W = SKEW_SAMPLE
    for n in (1, 2, 3):
        got = require_shape(exp_series(W, n), (3, 3))
        expected = _partial(W, 0, n - 1)
        if not close(got, expected, 1e-12):
            raise Mismatch(f"exp_series(W, {n}) differs from the sum of its first {n} terms "
                           f"({off_by(got, expected)})", _series_hint(got, W, n))


@public_check("exp_series", "many terms sum to a rotation: the quarter turn about z")
def _(exp_series):
    W = np.array([[0.0, -np.pi / 2, 0.0], [np.pi / 2, 0.0, 0.0], [0.0, 0.0, 0.0]])
    got = require_shape(exp_series(W, 30), (3, 3))
    if not close(got, QUARTER_TURN_Z, 1e-12):
        raise Mismatch(f"30 terms of exp([π/2 e_z]×) give x → {fmt(got[:, 0])}, expected [0, 1, 0] "
                       f"({off_by(got, QUARTER_TURN_Z)})", _series_hint(got, W, 30))


# ---------------------------------------------------------------- exp_so3
def _exp_hint(got, w):
    w = np.asarray(w, dtype=float)
    angle = float(np.linalg.norm(w))
    expected = Exp(w)
    if angle > 0.0 and np.array_equal(got, np.eye(3)):
        return f"returned exactly I: the turn of {angle:.3g} rad was dropped; use the Taylor coefficients, never return I"
    if _explains(got, expected.T, expected):
        return "got the inverse rotation: check the sign of the sin θ term, R = I + sin θ K + ..."
    if angle > 0.0:
        K, W = _skew(w / angle), _skew(w)
        if _explains(got, np.eye(3) + (1 - np.cos(angle)) * K + np.sin(angle) * K @ K, expected):
            return "the coefficients are swapped: R = I + sin θ K + (1 - cos θ) K², sin θ goes with K"
        if _explains(got, np.eye(3) + np.sin(angle) * W + (1 - np.cos(angle)) * W @ W, expected):
            return "Rodrigues' formula needs the unit axis: K = [w/θ]×, not [w]× (θ = |w| is in sin θ and cos θ)"
    return "R = I + sin θ K + (1 - cos θ) K² with K = [w/θ]× and θ = |w|"


@public_check("exp_so3", "a quarter turn about z sends x to y")
def _(exp_so3):
    R = require_shape(exp_so3([0.0, 0.0, np.pi / 2]), (3, 3))
    if not close(R, QUARTER_TURN_Z, 1e-12):
        raise Mismatch(f"exp_so3([0, 0, π/2]) sends x to {fmt(R[:, 0])}, expected [0, 1, 0] "
                       f"({off_by(R, QUARTER_TURN_Z)})", _exp_hint(R, [0.0, 0.0, np.pi / 2]))


@public_check("exp_so3", "returns a rotation that leaves its axis fixed")
def _(exp_so3):
    R = require_shape(exp_so3(W_SAMPLE), (3, 3))
    problem = rotation_problem(R, 1e-12)
    if problem:
        raise Mismatch(f"exp_so3(w) is not a rotation: {problem}", _exp_hint(R, W_SAMPLE))
    if not close(R @ W_SAMPLE, W_SAMPLE, 1e-12):
        raise Mismatch(f"exp_so3(w) moves its own axis w ({off_by(R @ W_SAMPLE, W_SAMPLE)})", _exp_hint(R, W_SAMPLE))


@public_check("exp_so3", "w = 0 gives I, and a tiny turn (1e-8 rad) is not lost")
def _(exp_so3):
    got = require_shape(exp_so3([0.0, 0.0, 0.0]), (3, 3))
    if not close(got, np.eye(3), 1e-15):
        raise Mismatch(f"exp_so3(0) is not the identity ({off_by(got, np.eye(3))})",
                       "at θ = 0 use the limits sin θ/θ → 1, (1 - cos θ)/θ² → 1/2")
    w = [0.0, 0.0, 1e-8]
    got = require_shape(exp_so3(w), (3, 3))
    if not close(got, _rot_z(1e-8), 1e-15):
        raise Mismatch(f"exp_so3([0, 0, 1e-8]) is {off_by(got, _rot_z(1e-8))} (R[1, 0] = {got[1, 0]:.3g}, "
                       "expected 1e-08)", _exp_hint(got, w))


# ---------------------------------------------------------------- log_so3
def _log_parts(R):
    """a = vee(R - Rᵀ)/2 = sin θ u, c = (tr R - 1)/2 = cos θ, and θ from atan2 and from (clipped) arccos."""
    R = np.asarray(R, dtype=float)
    a = 0.5 * np.array([R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]])
    c = 0.5 * (np.trace(R) - 1.0)
    return a, c, float(np.arctan2(np.linalg.norm(a), c)), float(np.arccos(np.clip(c, -1.0, 1.0)))


def _log_hint(got, R, expected):
    """The slip behind a wrong log_so3(R) = ``got``, found by computing what each slip returns for this R."""
    got, expected = np.asarray(got, dtype=float), np.asarray(expected, dtype=float)
    a, c, theta, theta_acos = _log_parts(R)
    angle = float(np.linalg.norm(expected))
    if not np.all(np.isfinite(got)):
        if abs(c) > 1.0:
            return "NaN: (tr R - 1)/2 is just outside [-1, 1] by rounding, and arccos of it is NaN: clip it first"
        if angle < 1e-3:
            return "NaN or inf at θ = 0: θ/sin θ is 0/0 there; use its series 1 + θ²/6 (or return 0) for tiny θ"
        return "NaN or inf near θ = π, where sin θ → 0: the log needs a branch there, with the axis from (R + Rᵀ)/2"
    if angle == 0.0:
        return "the identity's log is the zero vector"
    unit = expected / angle
    if _explains(got, -expected, expected):
        return "the opposite rotation: check the sign of the axis (vee(R - Rᵀ)/2 = sin θ · u points along u)"
    if _explains(got, 2.0 * expected, expected):
        return "twice the rotation vector: vee(R - Rᵀ) = 2 sin θ u, so the factor is θ/(2 sin θ)"
    if angle < 0.5 and _explains(got, a, expected):
        return (f"returned vee(R - Rᵀ)/2 = sin θ u, off by θ³/6 ≈ {angle ** 3 / 6:.1e}: you dropped the θ²/6 term, "
                "keep θ/sin θ ≈ 1 + θ²/6 for small θ")
    if _explains(got, theta_acos * unit, expected):
        if theta_acos == 0.0:
            return "returned zero for a tiny rotation: arccos rounds tiny angles to 0; use θ = atan2(|vee(R - Rᵀ)|/2, (tr R - 1)/2)"
        return (f"θ from arccos is off by {abs(theta_acos - angle):.1e}: arccos loses accuracy where its argument "
                "is near ±1; use θ = atan2(|vee(R - Rᵀ)|/2, (tr R - 1)/2)")
    no_branch = [t / np.sin(t) * a for t in (theta, theta_acos) if np.sin(t) != 0.0]
    if any(_explains(got, candidate, expected) for candidate in no_branch) or (
            angle > 3.0 and np.linalg.norm(got) <= 1e-3 * angle):
        return (f"θ/(2 sin θ)·vee(R - Rᵀ) divides two tiny numbers near π (here sin θ = {abs(np.sin(angle)):.1e}): the log "
                "needs its own branch near π, with the axis from (R + Rᵀ)/2 and its sign from R - Rᵀ")
    if angle > 3.0:
        return "the log is off near π: take the axis from the symmetric part (R + Rᵀ)/2 there, and its sign from R - Rᵀ"
    return "w = θ a/|a| with a = vee(R - Rᵀ)/2 and θ = atan2(|a|, (tr R - 1)/2)"


@public_check("log_so3", "undoes a quarter turn about z: [0, 0, π/2]")
def _(log_so3):
    got = require_shape(log_so3(QUARTER_TURN_Z), (3,))
    want = np.array([0.0, 0.0, np.pi / 2])
    if not close(got, want, 1e-12):
        raise Mismatch(f"log_so3 of the quarter turn is {off_by(got, want)}: returned {fmt(got)}",
                       _log_hint(got, QUARTER_TURN_Z, want))


@public_check("log_so3", "the identity gives 0, and tiny turns keep their relative accuracy")
def _(log_so3):
    got = require_shape(log_so3(np.eye(3)), (3,), "log_so3(I)", lambda got: _log_hint(got, np.eye(3), np.zeros(3)))
    if not close(got, np.zeros(3), 1e-15):
        raise Mismatch(f"log_so3(I) returned {fmt(got)}", _log_hint(got, np.eye(3), np.zeros(3)))
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    for angle in (1e-8, 1e-3):
        want = angle * axis
        R = Exp(want)
        got = require_shape(log_so3(R), (3,), f"log_so3 at θ = {angle:g}", lambda got: _log_hint(got, R, want))
        if not close(got, want, 1e-15 + 1e-10 * angle):
            raise Mismatch(f"log_so3 of a {angle:g} rad turn is {off_by(got, want)} "
                           f"(relative {np.max(np.abs(got - want)) / angle:.2g}): returned {got}",
                           _log_hint(got, R, want))


@public_check("log_so3", "exact at θ = π, also about (1, 1, 1)/√3 (either sign)")
def _(log_so3):
    for name, R, axis in [("the half turn about z", HALF_TURN_Z, np.array([0.0, 0.0, 1.0])),
                          ("the half turn about (1, 1, 1)/√3", HALF_TURN_DIAGONAL, DIAGONAL)]:
        got = require_shape(log_so3(R), (3,), f"log_so3 of {name}", lambda got: _log_hint(got, R, np.pi * axis))
        want = np.pi * axis if np.linalg.norm(got - np.pi * axis) <= np.linalg.norm(got + np.pi * axis) \
            else -np.pi * axis
        if not close(got, want, 1e-10):
            raise Mismatch(f"log_so3 of {name} is {off_by(got, want)} (either sign accepted): returned {fmt(got)}",
                           _log_hint(got, R, want))


@public_check("log_so3", "just below π the sign of the axis is right")
def _(log_so3):
    angle = np.pi - 1e-6
    axis = np.array([0.0, -0.6, -0.8])            # its largest component is negative
    R = Exp(angle * axis)
    got = require_shape(log_so3(R), (3,))
    want = angle * axis
    if not close(got, want, 1e-8):
        raise Mismatch(f"log_so3 is {off_by(got, want)} at θ = π - 1e-6 about {fmt(axis)}: returned {fmt(got)}",
                       _log_hint(got, R, want))


# ---------------------------------------------------------------- axis_angle
def _theta_hint(theta, R, true_angle):
    _, _, _, theta_acos = _log_parts(R)
    if _explains(theta, np.degrees(true_angle), true_angle):
        return "θ is in degrees (57.3 × the value in radians): the course works in radians"
    if _explains(theta, theta_acos, true_angle):
        return (f"θ from arccos is off by {abs(theta_acos - true_angle):.1e}: arccos is inaccurate next to ±1; "
                "use θ = atan2(|vee(R - Rᵀ)|/2, (tr R - 1)/2)")
    return "θ = atan2(|vee(R - Rᵀ)|/2, (tr R - 1)/2), in radians, in [0, π]"


def _pair(value, R):
    if not isinstance(value, (tuple, list)) or len(value) != 2:
        raise Mismatch(f"returned {type(value).__name__}, expected a pair (u, theta)", "return u, theta")
    c = 0.5 * (np.trace(R) - 1.0)
    theta = require_shape(value[1], (), "θ", lambda _: (
        "(tr R - 1)/2 is just above 1 by rounding, so arccos gives NaN: clip (tr R - 1)/2 to [-1, 1] before "
        "arccos (or use atan2)" if abs(c) > 1.0 else "θ must be a number"))
    u = require_shape(value[0], (3,), "u", lambda _: (
        "u = vee(R - Rᵀ)/(2 sin θ) is 0/0 at θ = 0: the axis is arbitrary there, return [1, 0, 0]"
        if theta == 0.0 else "look for a division by a vanishing sin θ or norm"))
    return u, float(theta)


@public_check("axis_angle", "a quarter turn about z: u = [0, 0, 1], θ = π/2")
def _(axis_angle):
    u, theta = _pair(axis_angle(QUARTER_TURN_Z), QUARTER_TURN_Z)
    if not close(theta, np.pi / 2, 1e-12):
        raise Mismatch(f"θ = {theta:.6g}, expected π/2 ({off_by(theta, np.pi / 2)})",
                       _theta_hint(theta, QUARTER_TURN_Z, np.pi / 2))
    if not close(u, [0.0, 0.0, 1.0], 1e-12):
        raise Mismatch(f"got u = {fmt(u)}, expected u = [0, 0, 1] ({off_by(u, [0.0, 0.0, 1.0])})",
                       "u = vee(R - Rᵀ)/(2 sin θ) away from π")


@public_check("axis_angle", "the identity, also up to rounding (trace just above 3): θ = 0 with a unit axis (no NaN)")
def _(axis_angle):
    for name, R in [("the identity", np.eye(3)), ("an identity up to rounding", np.diag([1.0 + 4.5e-16, 1.0, 1.0]))]:
        u, theta = _pair(axis_angle(R), R)
        if not (close(theta, 0.0, 1e-15) and close(np.linalg.norm(u), 1.0, 1e-12)):
            raise Mismatch(f"for {name} got u = {fmt(u)}, θ = {theta:.3g}",
                           "at θ = 0 the axis is arbitrary: return the unit vector [1, 0, 0]")


@public_check("axis_angle", "a half turn about (1, 1, 1)/√3: θ = π, u = ±(1, 1, 1)/√3")
def _(axis_angle):
    R = HALF_TURN_DIAGONAL
    u, theta = _pair(axis_angle(R), R)
    if not close(theta, np.pi, 1e-12):
        raise Mismatch(f"θ = {theta:.12f} is {off_by(theta, np.pi)} from π", _theta_hint(theta, R, np.pi))
    if not (close(u, DIAGONAL, 1e-10) or close(u, -DIAGONAL, 1e-10)):
        a = _log_parts(R)[0]
        raise Mismatch(f"got u = {fmt(u)}, expected ±(1, 1, 1)/√3",
                       "at θ = π, R - Rᵀ is zero up to rounding and carries no axis: take u from (R + I)/2, "
                       "the column with the largest diagonal entry" if np.linalg.norm(a) <= 1e-9 else
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


def _eigen_hint(u, R):
    """The slip behind a wrong axis u of R, found by computing what each slip returns (up to sign)."""
    values, vectors = np.linalg.eig(R)
    k = int(np.argmin(np.abs(values - 1.0)))

    def unit(v):
        v = np.real(np.asarray(v))
        return v / np.linalg.norm(v)

    def same_line(v):
        return min(np.max(np.abs(u - v)), np.max(np.abs(u + v))) <= 1e-6

    sym_values, sym_vectors = np.linalg.eigh(R)
    candidates = [
        (unit(vectors[k]), "that is a row of the eigenvector matrix: eigenvectors are its columns, vectors[:, k]"),
        (unit(vectors[:, 0]), f"that is the first eigenvector, whose eigenvalue is {values[0]:.3g}, not 1: "
                              "take k = argmin |λ - 1|"),
        (np.linalg.svd(R)[2][-1], "that is the SVD null space of R, but R is invertible: the axis spans the "
                                  "null space of R - I"),
        (sym_vectors[:, int(np.argmin(np.abs(sym_values - 1.0)))],
         "np.linalg.eigh assumes a symmetric matrix (it reads one triangle of R): use np.linalg.eig"),
    ]
    for candidate, hint in candidates:
        if same_line(candidate) and not same_line(unit(vectors[:, k])):
            return hint
    return "u must be the eigenvector of the eigenvalue 1: the column vectors[:, k] with k = argmin |λ - 1|"


@public_check("axis_from_eigen", "returns a real unit vector with R u = u")
def _(axis_from_eigen):
    angle = 2.0
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    R = Exp(angle * axis)
    u = _real(axis_from_eigen(R))
    if not close(np.linalg.norm(u), 1.0, 1e-12):
        raise Mismatch(f"|u| = {np.linalg.norm(u):.6g}", "normalise the eigenvector")
    if not close(R @ u, u, 1e-10):
        raise Mismatch(f"R u ≠ u for u = {fmt(u)} (|R u - u| up to {np.max(np.abs(R @ u - u)):.2g})",
                       _eigen_hint(u, R))


@public_check("axis_from_eigen", "a half turn about z: u = ±e_z")
def _(axis_from_eigen):
    u = _real(axis_from_eigen(HALF_TURN_Z))
    if not (close(u, [0.0, 0.0, 1.0], 1e-12) or close(u, [0.0, 0.0, -1.0], 1e-12)):
        raise Mismatch(f"got {fmt(u)}, expected ±e_z", _eigen_hint(u, HALF_TURN_Z))
