"""Public checks for lesson 02: groups and SO(3).

The checks hand the student's functions small, fully known structures —
quarter turns, numbers, cross products — whose verdicts are facts of the
lesson, and name the usual slip when a verdict is wrong.
"""

import numpy as np

from .. import hints
from ..checking import Mismatch, public_check
from ..diagnose import ALLCLOSE_HINT
from ..lie import Exp
from .tolerance import GAP_EXPONENTS, boundary_problem

QUARTER_TURN_Z = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
QUARTER_TURN_X = np.array([[1.0, 0.0, 0.0], [0.0, 0.0, -1.0], [0.0, 1.0, 0.0]])
KEYS = ("closure", "identity", "inverse", "associativity")


def _matmul(a, b):
    return np.asarray(a, dtype=float) @ np.asarray(b, dtype=float)


def _add(a, b):
    return np.asarray(a, dtype=float) + np.asarray(b, dtype=float)


def _multiply(a, b):
    return a * b


def _reciprocal(a):
    with np.errstate(divide="ignore"):
        return 1.0 / np.float64(a)


def _is_real(x):
    return bool(np.all(np.isfinite(x)))


def _is_rotation(M):
    M = np.asarray(M, dtype=float)
    if M.shape != (3, 3) or not np.all(np.isfinite(M)):
        return False
    return bool(np.max(np.abs(M.T @ M - np.eye(3))) <= 1e-9 and np.linalg.det(M) > 0)


def _is_reflection(M):
    M = np.asarray(M, dtype=float)
    if M.shape != (3, 3) or not np.all(np.isfinite(M)):
        return False
    return bool(np.max(np.abs(M.T @ M - np.eye(3))) <= 1e-9 and np.linalg.det(M) < 0)


def _closure_uses_matmul(check_group_axioms):
    """True when closure looks computed with @ instead of op: mirrors under a ∘ b = b are closed
    (b is a mirror), but their matrix products are rotations."""
    mirrors = [np.diag([1.0, 1.0, -1.0]), np.diag([-1.0, 1.0, 1.0])]
    try:
        value = check_group_axioms(mirrors, lambda a, b: np.array(b, dtype=float), np.eye(3),
                                   lambda a: np.asarray(a).T, _is_reflection)
    except Exception:
        return False
    return isinstance(value, dict) and value.get("closure") is False


def _verdict(result):
    """The dict returned by check_group_axioms, validated."""
    if not isinstance(result, dict):
        raise Mismatch(f"returned {type(result).__name__}, expected a dict",
                       hints.RETURN_CLOSURE_IDENTITY_INVERSE_HINT)
    missing = [k for k in KEYS if k not in result]
    if missing:
        raise Mismatch(f"the dict has no key {missing[0]!r} (keys: {sorted(map(str, result))})",
                       hints.USE_EXACTLY_KEYS_CLOSURE_HINT)
    for key in KEYS:
        if not isinstance(result[key], (bool, np.bool_)):
            raise Mismatch(f"result[{key!r}] is {result[key]!r}, not True or False", "wrap it in bool(...)")
    return {k: bool(result[k]) for k in KEYS}


def _expect(got, expected, name, hint_for):
    for key in KEYS:
        if got[key] != expected[key]:
            raise Mismatch(f"{name}: {key} came out {got[key]}, expected {expected[key]}", hint_for.get(key))


# ---------------------------------------------------------------- check_group_axioms
@public_check("check_group_axioms", "returns a dict of four booleans; nonzero reals under * pass every axiom")
def _(check_group_axioms):
    got = _verdict(check_group_axioms([2.0, -0.5, 4.0, 0.25], _multiply, 1.0, _reciprocal,
                                      lambda x: bool(np.isfinite(x) and x != 0)))
    _expect(got, dict.fromkeys(KEYS, True), "nonzero reals", {
        "associativity": "(2·(-0.5))·4 and 2·((-0.5)·4) differ only by rounding: compare with tol"})


@public_check("check_group_axioms", "quarter turns under the matrix product pass every axiom")
def _(check_group_axioms):
    samples = [np.eye(3), QUARTER_TURN_Z, QUARTER_TURN_Z @ QUARTER_TURN_Z, QUARTER_TURN_X]
    got = _verdict(check_group_axioms(samples, _matmul, np.eye(3), lambda a: np.asarray(a).T, _is_rotation))
    _expect(got, dict.fromkeys(KEYS, True), "rotations under @", {})


@public_check("check_group_axioms", "rotations under addition fail closure, identity and inverse")
def _(check_group_axioms):
    got = _verdict(check_group_axioms([QUARTER_TURN_Z, QUARTER_TURN_X], _add, np.zeros((3, 3)),
                                      lambda a: -np.asarray(a), _is_rotation))
    closure_hint = hints.CLOSURE_ASKS_MEMBER_OP_B_HINT
    if got["closure"] and _closure_uses_matmul(check_group_axioms):
        closure_hint = (hints.CLOSURE_TESTED_INSTEAD_OP_HINT)
    _expect(got, {"closure": False, "identity": False, "inverse": False, "associativity": True},
            "rotations under +", {
                "closure": closure_hint,
                "identity": "the identity must belong to the set: also check is_member(identity)",
                "inverse": "each inverse must belong to the set: also check is_member(inverse(a)) (-R has det -1)",
                "associativity": "compare op(op(a, b), c) with op(a, op(b, c)) using op"})


@public_check("check_group_axioms", "all reals under * (0 included): only the inverse fails")
def _(check_group_axioms):
    got = _verdict(check_group_axioms([2.0, 0.0, -3.0], _multiply, 1.0, _reciprocal, _is_real))
    _expect(got, {"closure": True, "identity": True, "inverse": False, "associativity": True},
            "reals with 0", {
                "inverse": "1/0 is inf: is_member(inf) is False, and 0·inf is NaN, which must not count as equal",
                "closure": hints.CLOSURE_ASKS_MEMBER_OP_HINT})


# Structures where 1 is an identity, and inverse(a) = 1 an inverse, on one side only:
# (op, rule, side, the product that shows it, the inverse's product, the hint)
ONE_SIDED = (
    (lambda a, b: b, "a ∘ b = b", "left", "2 ∘ 1 = 1", "inverse(2) ∘ 2 = 2 ≠ 1",
     hints.RIGHT_IDENTITY_UNCHECKED_HINT),
    (lambda a, b: a, "a ∘ b = a", "right", "1 ∘ 2 = 1", "2 ∘ inverse(2) = 2 ≠ 1",
     hints.LEFT_IDENTITY_UNCHECKED_HINT),
)


@public_check("check_group_axioms", "catches one-sided identities (a ∘ b = b, a ∘ b = a) and a non-associative ×")
def _(check_group_axioms):
    for op, rule, side, witness, inverse_witness, hint in ONE_SIDED:
        got = _verdict(check_group_axioms([1.0, 2.0, 3.0], op, 1.0, lambda a: 1.0, _is_real))
        if got["identity"]:
            raise Mismatch(f"with {rule}, 1 is only a {side} identity ({witness}), yet identity came out True", hint)
        if got["inverse"]:
            raise Mismatch(f"with {rule} and inverse(a) = 1, {inverse_witness}, yet inverse came out True",
                           "check both op(a, inverse(a)) and op(inverse(a), a)")
    vectors = [np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0]), np.array([0.0, 1.0, 1.0])]
    got = _verdict(check_group_axioms(vectors, np.cross, np.zeros(3), lambda a: -np.asarray(a), _is_real))
    if got["associativity"]:
        raise Mismatch("the cross product is not associative, yet associativity came out True",
                       "loop over every ordered triple (a, b, c), repeats included")


@public_check("check_group_axioms", "compares with tol: generic rotations under @ pass every axiom")
def _(check_group_axioms):
    samples = [Exp([0.3, -0.2, 0.9]), Exp([1.1, 0.4, -0.7]), Exp([-0.5, 2.0, 0.1])]
    got = _verdict(check_group_axioms(samples, _matmul, np.eye(3), lambda a: np.asarray(a).T, _is_rotation))
    _expect(got, dict.fromkeys(KEYS, True), "generic rotations under @",
            dict.fromkeys(KEYS, "products of generic rotations differ by rounding (~1e-16): compare with tol, "
                                "never with =="))


@public_check("check_group_axioms", "tol is an absolute tolerance: an identity off by 2e-7 fails at tol=1e-9")
def _(check_group_axioms):
    args = ([3.0, -0.25, 8.0], _multiply, 1.0 + 2e-7, _reciprocal, lambda x: bool(np.isfinite(x) and x != 0))
    if not _verdict(check_group_axioms(*args, tol=1e-5))["identity"]:
        raise Mismatch("with identity 1 + 2e-7 and tol=1e-5, identity came out False", "compare with the tol argument")
    if _verdict(check_group_axioms(*args, tol=1e-9))["identity"]:
        allclose = all(np.allclose((1.0 + 2e-7) * a, a, atol=1e-9) for a in args[0])
        raise Mismatch("with identity 1 + 2e-7 and tol=1e-9, identity came out True although 8·(1 + 2e-7) "
                       "differs from 8 by 1.6e-6",
                       ALLCLOSE_HINT if allclose else "compare max |op(identity, a) - a| with tol")



@public_check("check_group_axioms", "tol is the largest accepted difference: just below, at and just above it")
def _(check_group_axioms):
    for k in GAP_EXPONENTS:
        identity = 1.0 + 2.0**-k  # under ×, op(identity, 4) - 4 = 4·2^-k exactly, the largest gap
        name = f"check_group_axioms([4, -0.5, 2], ×, identity 1 + 2^-{k}, tol)['identity']"

        def verdict(tol):
            nonzero = lambda x: bool(np.isfinite(x) and x != 0)  # noqa: E731
            return _verdict(check_group_axioms([4.0, -0.5, 2.0], _multiply, identity, _reciprocal, nonzero,
                                               tol=tol))["identity"]

        problem = boundary_problem(verdict, 4.0 * 2.0**-k, "max |op(identity, a) - a|", name)
        if problem:
            raise Mismatch(*problem)

# ---------------------------------------------------------------- commutes
SAME_ORDER_HINT = "op(a, b) looks compared with itself: swap the arguments in the second product, op(b, a)"
IGNORES_OP_HINT = "the verdict follows a @ b whatever op is given: compare op(a, b) with op(b, a)"
EXACT_HINT = "the two products differ by ~1e-16: compare with tol, never with =="
FIXED_TOL_HINT = "the verdict does not change with tol: compare with the tol argument, not a fixed number"
GENERAL_HINT = "compare max |op(a, b) - op(b, a)| with tol"


def commutes_slip_hint(big, cross, rounding, loose, strict, rtol):
    """The slip behind a wrong ``commutes`` from its verdicts on six probes, or None when none fits.

    Shared with the hidden suite, which asks the same six questions on its own data: ``big``, quarter
    turns about x and z (do not commute); ``cross``, e_x and e_y under × (do not commute); ``rounding``,
    two rotations about one axis (commute up to ~1e-16); ``loose`` and ``strict``, products that differ by
    1e-7 where the entries are 0, at tol=1e-5 and tol=1e-9; ``rtol``, dense products that differ by ~1e-6,
    at tol=1e-9.
    """
    if big and cross:
        return SAME_ORDER_HINT
    if cross:
        return IGNORES_OP_HINT
    if not rounding and not loose:
        return EXACT_HINT
    if loose and strict:
        return FIXED_TOL_HINT
    if loose and not strict and rtol:
        return ALLCLOSE_HINT
    return None


def _commutes_slip(commutes):
    """Name the typical slip behind a wrong commutes from a few more calls, or GENERAL_HINT when none fits.

    Quarter turns and e_x, e_y under × do not commute (all True: the arguments were never swapped; only ×
    wrong: op ignored); rotations about one axis commute up to ~1e-16 (rejected: ==); products differing by
    1e-7 where the entries are 0 (rtol cannot help) accepted at tol=1e-9 too: tol ignored; dense products
    differing by 1e-6 accepted at tol=1e-9 while that pair is right: np.allclose's rtol.
    """
    tiny_a, tiny_b = np.zeros((3, 3)), np.zeros((3, 3))
    tiny_a[0, 1], tiny_b[1, 0] = 1e-3, 1e-4                 # products 1e-7·E₀₀ and 1e-7·E₁₁
    dense = np.ones((3, 3)) + np.diag([1.0, 2.0, 3.0])
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    try:
        big = commutes(QUARTER_TURN_X, QUARTER_TURN_Z, _matmul)
        cross = commutes(np.eye(3)[0], np.eye(3)[1], np.cross)
        rounding = commutes(Exp(0.4 * axis), Exp(1.3 * axis), _matmul)
        loose = commutes(tiny_a, tiny_b, _matmul, tol=1e-5)
        strict = commutes(tiny_a, tiny_b, _matmul, tol=1e-9)
        rtol = commutes(dense, dense + 1e-6 * np.eye(3)[[1, 0, 2]], _matmul, tol=1e-9)
    except Exception:
        return GENERAL_HINT
    return commutes_slip_hint(big, cross, rounding, loose, strict, rtol) or GENERAL_HINT


@public_check("commutes", "rotations about one axis commute, even though rounding differs")
def _(commutes):
    axis = np.array([2.0, -1.0, 2.0]) / 3.0
    verdict = commutes(Exp(0.4 * axis), Exp(1.3 * axis), _matmul)
    if not isinstance(verdict, (bool, np.bool_)):
        raise Mismatch(f"returned {verdict!r} ({type(verdict).__name__}), not True or False",
                       "return bool(...) of one comparison, not an array")
    if not verdict:
        gap = np.max(np.abs(Exp(0.4 * axis) @ Exp(1.3 * axis) - Exp(1.3 * axis) @ Exp(0.4 * axis)))
        raise Mismatch(f"said two rotations about the same axis do not commute (their products differ by "
                       f"{gap:.2g})", _commutes_slip(commutes))


@public_check("commutes", "quarter turns about x and z do not commute")
def _(commutes):
    if commutes(QUARTER_TURN_X, QUARTER_TURN_Z, _matmul):
        raise Mismatch("said the quarter turns about x and z commute (their products differ by 2)",
                       _commutes_slip(commutes))


@public_check("commutes", "uses the op it is given (numbers under *, vectors under ×)")
def _(commutes):
    try:
        numbers = commutes(2.0, -3.5, _multiply)
    except Exception as error:
        raise Mismatch(f"commutes(2.0, -3.5, multiply) raised {type(error).__name__}: {error}",
                       _commutes_slip(commutes)) from None
    if not numbers:
        raise Mismatch("said 2 and -3.5 do not commute under multiplication", _commutes_slip(commutes))
    e_x, e_y = np.array([1.0, 0.0, 0.0]), np.array([0.0, 1.0, 0.0])
    if commutes(e_x, e_y, np.cross):
        raise Mismatch("said e_x and e_y commute under the cross product (e_x × e_y = -(e_y × e_x))",
                       _commutes_slip(commutes))


NAN_HINT = ("a NaN result never counts as equal: compare with max |x - y| <= tol, which is False for NaN "
            "(not ... > tol, which NaN passes)")


@public_check("commutes", "a NaN never counts as equal: commutes(NaN, 2, ×) is False")
def _(commutes):
    if commutes(float("nan"), 2.0, lambda a, b: a * b):
        raise Mismatch(hints.COMMUTES_NAN_CAME_OUT_HINT, NAN_HINT)


@public_check("commutes", "uses the tol argument")
def _(commutes):
    A, B = Exp([0.0, 0.0, 0.3]), Exp([1e-7, 0.0, 0.5])   # their products differ by about 3e-8
    if not commutes(A, B, _matmul, tol=1e-5):
        raise Mismatch("with tol=1e-5, a difference of 3e-8 was not accepted", _commutes_slip(commutes))
    if commutes(A, B, _matmul, tol=1e-9):
        raise Mismatch("with tol=1e-9, a difference of 3e-8 was accepted", _commutes_slip(commutes))


@public_check("commutes", "tol is an absolute tolerance, also for large entries")
def _(commutes):
    M = np.ones((3, 3)) + np.diag([1.0, 2.0, 3.0])
    B = M + 1e-6 * np.array([[0.0, 1.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.0]])
    gap = np.max(np.abs(M @ B - B @ M))
    if commutes(M, B, _matmul, tol=1e-9):
        raise Mismatch(f"with tol=1e-9, said two matrices commute whose products differ by {gap:.2g}",
                       _commutes_slip(commutes))


@public_check("commutes", "tol is the largest accepted entry of |op(a, b) - op(b, a)|: just below, at and just above it")
def _(commutes):
    for k in GAP_EXPONENTS:
        A, B = np.eye(3), np.eye(3)
        A[0, 1], B[1, 0] = 2.0**-k, 1.0  # two shears: A @ B - B @ A = diag(2^-k, -2^-k, 0), exact in binary
        name = f"commutes(I + 2^-{k} e₁e₂ᵀ, I + e₂e₁ᵀ, @, tol)"
        problem = boundary_problem(lambda tol: commutes(A, B, _matmul, tol=tol), 2.0**-k, "max |a @ b - b @ a|", name)
        if problem:
            raise Mismatch(*problem)
