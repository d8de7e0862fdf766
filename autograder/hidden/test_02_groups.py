"""Hidden checks for lesson 02: groups and SO(3).

The student's functions receive callables as named probes (``Probe("matmul")``)
that the sandbox rebuilds from ``autograder/sandbox/child/probes.py``. Each
structure below has a verdict that follows from the lesson's definitions:
(tolerances are absolute: data where np.allclose's rtol=1e-5 would swamp
tol, dense matrices and an identity off by 1e-7, are part of the suite;
floating-point products are never exactly associative, so == fails),
rotations under the product (a group), under addition (closure, identity and
inverse fail), reals with 0 under multiplication (the inverse fails), the
cross product (no identity, not associative), "keep the second" and "keep
the first" (one-sided identities and inverses, one of each side), reflections (no closure, no identity). A NaN never
counts as equal (max |x - y| <= tol is False for NaN). Every test calls the
student's functions of its own exercise only.
"""

import numpy as np
from scipy.spatial.transform import Rotation

from autograder.sandbox.session import StudentError
from coursekit import hints
from coursekit.checks import tolerance
from coursekit.checks.lesson02 import NAN_HINT, commutes_slip_hint

from .helpers import ALLCLOSE_HINT, Probe, Wrong, exercise, expect, expect_bool, random_rotations

KEYS = ("closure", "identity", "inverse", "associativity")
MIRROR = np.diag([1.0, 1.0, -1.0])


def _verdict(value, what):
    """The dict returned by check_group_axioms, as {key: bool}, or Wrong."""
    if not isinstance(value, dict):
        raise Wrong(f"{what} returned {type(value).__name__}, not a dict", hints.RETURN_CLOSURE_IDENTITY_INVERSE_HINT)
    missing = [k for k in KEYS if k not in value]
    if missing:
        raise Wrong(f"{what}: the dict has no key {missing[0]!r}", hints.USE_EXACTLY_KEYS_CLOSURE_HINT)
    return {k: expect_bool(value[k], f"{what}[{k!r}]") for k in KEYS}


def _expect_verdict(got, expected, what, hint_for=None):
    hint_for = hint_for or {}
    for key in KEYS:
        expect(
            got[key] == expected[key],
            f"{what}: {key} came out {got[key]}, expected {expected[key]}",
            hint_for.get(key, ""),
        )


ALL_TRUE = dict.fromkeys(KEYS, True)


# ---------------------------------------------------------------- check_group_axioms
def _closure_uses_matmul(student):
    """True when closure looks computed with @ instead of op: reflections under a ∘ b = b are closed
    (b is a reflection), but their matrix products are rotations."""
    reflections = [R @ MIRROR for R in random_rotations(3, seed=208)]
    try:
        value = student.check_group_axioms(
            reflections, Probe("second"), np.eye(3), Probe("transpose"), Probe("is_reflection")
        )
        return isinstance(value, dict) and value.get("closure") is False
    except StudentError:
        return False


def _allclose_accepts(pairs, tol):
    """True when np.allclose(x, y, atol=tol), with its default rtol, calls every pair (x, y) equal."""
    return all(np.allclose(x, y, atol=tol) for x, y in pairs)


@exercise("check_group_axioms", weight=3)
def test_check_group_axioms_so3_is_a_group(student):
    """random rotations under the matrix product pass all four axioms"""
    samples = list(random_rotations(6, seed=201))
    got = _verdict(
        student.check_group_axioms(samples, Probe("matmul"), np.eye(3), Probe("transpose"), Probe("is_rotation")),
        "check_group_axioms(SO(3), @)",
    )
    _expect_verdict(
        got,
        ALL_TRUE,
        "rotations under @",
        {
            "associativity": "(AB)C and A(BC) differ by rounding (~1e-16): compare with tol, not ==",
            "inverse": "compare op(a, inverse(a)) with the identity within tol",
            "identity": "compare op(identity, a) and op(a, identity) with a within tol",
        },
    )


@exercise("check_group_axioms", weight=3)
def test_check_group_axioms_so3_under_addition(student):
    """rotations under addition: closure, identity and inverse fail, associativity holds"""
    samples = list(random_rotations(4, seed=202))
    got = _verdict(
        student.check_group_axioms(samples, Probe("add"), np.zeros((3, 3)), Probe("negate"), Probe("is_rotation")),
        "check_group_axioms(SO(3), +)",
    )
    closure_hint = hints.CLOSURE_ASKS_MEMBER_OP_B_HINT
    if got["closure"] and _closure_uses_matmul(student):
        closure_hint = hints.CLOSURE_TESTED_INSTEAD_OP_HINT
    _expect_verdict(
        got,
        {"closure": False, "identity": False, "inverse": False, "associativity": True},
        "rotations under +",
        {
            "closure": closure_hint,
            "identity": "the identity must belong to the set: check is_member(identity)",
            "inverse": "each inverse must belong to the set: check is_member(inverse(a)) (-R has det -1)",
            "associativity": "(A + B) + C and A + (B + C) differ by rounding (~1e-16): compare "
            "op(op(a, b), c) with op(a, op(b, c)) within tol",
        },
    )


@exercise("check_group_axioms", weight=2)
def test_check_group_axioms_reals_with_zero(student):
    """all reals under multiplication fail only the inverse axiom (0 has none)"""
    got = _verdict(
        student.check_group_axioms(
            [2.0, -0.5, 0.0, 3.0], Probe("multiply"), 1.0, Probe("reciprocal"), Probe("is_finite")
        ),
        "check_group_axioms(reals, *)",
    )
    _expect_verdict(
        got,
        {"closure": True, "identity": True, "inverse": False, "associativity": True},
        "reals with 0 under *",
        {
            "inverse": "1/0 = inf is not a member, and 0·inf = NaN must not count as equal to 1",
            "closure": hints.CLOSURE_ASKS_MEMBER_OP_HINT,
        },
    )


@exercise("check_group_axioms", weight=2)
def test_check_group_axioms_nonzero_reals(student):
    """nonzero reals under multiplication pass all four axioms"""
    got = _verdict(
        student.check_group_axioms(
            [2.0, -0.5, 0.25, 3.0, -7.0], Probe("multiply"), 1.0, Probe("reciprocal"), Probe("is_nonzero")
        ),
        "check_group_axioms(nonzero reals, *)",
    )
    _expect_verdict(
        got,
        ALL_TRUE,
        "nonzero reals under *",
        {"associativity": "products of numbers differ by rounding: compare with tol"},
    )


@exercise("check_group_axioms", weight=2)
def test_check_group_axioms_cross_product(student):
    """vectors under the cross product: no identity and not associative"""
    vectors = list(np.random.default_rng(203).normal(size=(4, 3)))
    got = _verdict(
        student.check_group_axioms(vectors, Probe("cross"), np.zeros(3), Probe("negate"), Probe("is_finite")),
        "check_group_axioms(R^3, ×)",
    )
    _expect_verdict(
        got,
        {"closure": True, "identity": False, "inverse": True, "associativity": False},
        "3-vectors under ×",
        {
            "identity": "0 × a = 0, not a: compare op(identity, a) with a",
            "inverse": "a × (-a) = 0, which is the proposed identity: this part passes",
            "associativity": "check every ordered triple with op: (a × b) × c ≠ a × (b × c)",
        },
    )


# Structures where 1 is an identity, and Probe("constant", 1.0) an inverse, on one side only:
# (probe, rule, label, identity hint, inverse hint)
ONE_SIDED = (
    (
        "second",
        "a ∘ b = b",
        "'keep the second'",
        hints.RIGHT_IDENTITY_UNCHECKED_HINT,
        "a ∘ 1 = 1, but 1 ∘ a = a: check op(inverse(a), a) as well as op(a, inverse(a))",
    ),
    (
        "first",
        "a ∘ b = a",
        "'keep the first'",
        hints.LEFT_IDENTITY_UNCHECKED_HINT,
        "1 ∘ a = 1, but a ∘ 1 = a: check op(a, inverse(a)) as well as op(inverse(a), a)",
    ),
)


@exercise("check_group_axioms", weight=2)
def test_check_group_axioms_both_sides(student):
    """checks identity and inverses from both sides (a ∘ b = b has only left identities, a ∘ b = a only right
    ones)"""
    for probe, rule, label, identity_hint, inverse_hint in ONE_SIDED:
        got = _verdict(
            student.check_group_axioms([1.0, 2.0, -3.0], Probe(probe), 1.0, Probe("constant", 1.0), Probe("is_finite")),
            f"check_group_axioms({rule})",
        )
        _expect_verdict(
            got,
            {"closure": True, "identity": False, "inverse": False, "associativity": True},
            f"{label} ({rule})",
            {"identity": identity_hint, "inverse": inverse_hint},
        )


@exercise("check_group_axioms", weight=2)
def test_check_group_axioms_orthogonal_and_reflections(student):
    """O(3) is a group; the reflections alone fail closure and identity"""
    rotations = list(random_rotations(3, seed=204))
    reflections = [R @ MIRROR for R in random_rotations(3, seed=205)]
    got = _verdict(
        student.check_group_axioms(
            rotations + reflections, Probe("matmul"), np.eye(3), Probe("transpose"), Probe("is_orthogonal")
        ),
        "check_group_axioms(O(3), @)",
    )
    _expect_verdict(got, ALL_TRUE, "O(3) under @")
    got = _verdict(
        student.check_group_axioms(reflections, Probe("matmul"), np.eye(3), Probe("transpose"), Probe("is_reflection")),
        "check_group_axioms(reflections, @)",
    )
    _expect_verdict(
        got,
        {"closure": False, "identity": False, "inverse": True, "associativity": True},
        "reflections under @",
        {
            "closure": "the product of two reflections is a rotation: test is_member(op(a, b))",
            "identity": "I is not a reflection: check is_member(identity)",
        },
    )


@exercise("check_group_axioms", weight=1)
def test_check_group_axioms_uses_tol(student):
    """uses tol: rotations with 1e-7 noise pass with tol=1e-5, fail the inverse with tol=1e-9; a NaN never
    counts as equal (NaN among the reals under ×: not associative)"""
    noise = np.random.default_rng(206).normal(size=(4, 3, 3))
    samples = [R + 1e-7 * n for R, n in zip(random_rotations(4, seed=207), noise)]
    args = (samples, Probe("matmul"), np.eye(3), Probe("transpose"), Probe("is_rotation_within", 1e-4))
    loose = _verdict(student.check_group_axioms(*args, tol=1e-5), "check_group_axioms(..., tol=1e-5)")
    _expect_verdict(
        loose,
        ALL_TRUE,
        "noisy rotations with tol=1e-5",
        dict.fromkeys(KEYS, "compare with the tol argument, not a fixed number"),
    )
    strict = _verdict(student.check_group_axioms(*args, tol=1e-9), "check_group_axioms(..., tol=1e-9)")
    gaps = [np.max(np.abs(R @ R.T - np.eye(3))) for R in samples]
    pairs = [(R @ R.T, np.eye(3)) for R in samples] + [(R.T @ R, np.eye(3)) for R in samples]
    expect(
        strict["inverse"] is False,
        f"noisy rotations with tol=1e-9: inverse came out True, but "
        f"R @ Rᵀ differs from I by up to {max(gaps):.2g} > tol",
        lambda: (
            ALLCLOSE_HINT if _allclose_accepts(pairs, 1e-9) else "compare max |op(a, inverse(a)) - identity| with tol"
        ),
    )
    got = _verdict(
        student.check_group_axioms([np.nan, 2.0], Probe("multiply"), 1.0, Probe("reciprocal"), Probe("is_finite")),
        "check_group_axioms([NaN, 2], ×)",
    )
    expect(got["associativity"] is False, "with NaN among the products, associativity came out True", NAN_HINT)


@exercise("check_group_axioms", weight=1)
def test_check_group_axioms_absolute_tolerance(student):
    """tol is an absolute tolerance: an identity off by 1e-7 passes with tol=1e-5, fails with tol=1e-9"""
    args = ([2.0, -0.5, 4.0], Probe("multiply"), 1.0 + 1e-7, Probe("reciprocal"), Probe("is_nonzero"))
    loose = _verdict(student.check_group_axioms(*args, tol=1e-5), "check_group_axioms(..., tol=1e-5)")
    expect(
        loose["identity"],
        "with identity 1 + 1e-7 and tol=1e-5, identity came out False",
        "compare with the tol argument, not a fixed number",
    )
    strict = _verdict(student.check_group_axioms(*args, tol=1e-9), "check_group_axioms(..., tol=1e-9)")
    pairs = [((1.0 + 1e-7) * a, a) for a in args[0]]
    expect(
        not strict["identity"],
        "with identity 1 + 1e-7 and tol=1e-9, identity came out True although (1 + 1e-7)·4 differs from 4 by 4e-7",
        lambda: ALLCLOSE_HINT if _allclose_accepts(pairs, 1e-9) else "compare max |op(identity, a) - a| with tol",
    )


@exercise("check_group_axioms", weight=1)
def test_check_group_axioms_single_sample(student):
    """works with a single sample (the identity alone is a group)"""
    got = _verdict(
        student.check_group_axioms([np.eye(3)], Probe("matmul"), np.eye(3), Probe("transpose"), Probe("is_rotation")),
        "check_group_axioms([I], @)",
    )
    _expect_verdict(got, ALL_TRUE, "the trivial group {I}")


@exercise("check_group_axioms", weight=1)
def test_check_group_axioms_tol_boundary(student):
    """tol is the largest accepted difference: an identity 1 + 2^-k under ×, its largest gap 4·2^-k exact in
    binary, at tol 0.1 % below, equal to and 0.1 % above the gap, k = 8 … 26"""
    samples = [4.0, -0.5, 2.0]
    for k in tolerance.GAP_EXPONENTS:
        identity = 1.0 + 2.0**-k
        call = f"check_group_axioms([4, -0.5, 2], ×, identity 1 + 2^-{k}, tol)"

        def verdict(tol):
            value = student.check_group_axioms(
                samples, Probe("multiply"), identity, Probe("reciprocal"), Probe("is_nonzero"), tol=tol
            )
            return _verdict(value, call)["identity"]

        problem = tolerance.boundary_problem(verdict, 4.0 * 2.0**-k, "max |op(identity, a) - a|", f"{call}['identity']")
        if problem:
            raise Wrong(*problem)


# ---------------------------------------------------------------- commutes
def _commutes(student, a, b, op, what, **kwargs):
    return expect_bool(student.commutes(a, b, op, **kwargs), what)


def _about_axis(axis, angle):
    axis = np.asarray(axis, dtype=float)
    return Rotation.from_rotvec(angle * axis / np.linalg.norm(axis)).as_matrix()


def _commutes_slip(student):
    """Name the typical slip behind a wrong commutes from six more calls whose verdicts each slip gets wrong
    in its own way, or None when none fits:

    - quarter turns about x and z (do not commute) and e_x, e_y under × (do not commute): every verdict True
      means the arguments were never swapped; only the × verdict wrong means op was ignored for @;
    - two rotations about one axis (commute; their products differ by ~1e-16) rejected: ==;
    - nilpotent matrices whose products differ by 1e-7 where the entries are 0 (rtol cannot help): accepted
      at tol=1e-9 as well as at tol=1e-5 means tol is ignored;
    - dense matrices (entries ~5) whose products differ by ~1e-6 accepted at tol=1e-9 while the previous
      pair is right: np.allclose's rtol.
    """
    quarter_x, quarter_z = _about_axis([1.0, 0.0, 0.0], np.pi / 2), _about_axis([0.0, 0.0, 1.0], np.pi / 2)
    axis = np.array([2.0, -1.0, 2.0])
    tiny_a, tiny_b = np.zeros((3, 3)), np.zeros((3, 3))
    tiny_a[0, 1], tiny_b[1, 0] = 1e-3, 1e-4  # products 1e-7·E₀₀ and 1e-7·E₁₁
    rng = np.random.default_rng(218)
    dense = rng.uniform(1.0, 2.0, (3, 3))
    try:
        big = _commutes(student, quarter_x, quarter_z, Probe("matmul"), "commutes")
        cross = _commutes(student, np.eye(3)[0], np.eye(3)[1], Probe("cross"), "commutes")
        rounding = _commutes(student, _about_axis(axis, 0.4), _about_axis(axis, 1.3), Probe("matmul"), "commutes")
        loose = _commutes(student, tiny_a, tiny_b, Probe("matmul"), "commutes", tol=1e-5)
        strict = _commutes(student, tiny_a, tiny_b, Probe("matmul"), "commutes", tol=1e-9)
        rtol = _commutes(student, dense, dense + 1e-6 * rng.normal(size=(3, 3)), Probe("matmul"), "commutes", tol=1e-9)
    except (StudentError, Wrong):
        return None
    return commutes_slip_hint(big, cross, rounding, loose, strict, rtol)


def _expect_commutes(student, condition, reason, otherwise):
    """Raise Wrong unless ``condition``, with the slip found by :func:`_commutes_slip` or ``otherwise``."""
    if not condition:
        raise Wrong(reason, _commutes_slip(student) or otherwise)


@exercise("commutes", weight=3)
def test_commutes_same_axis(student):
    """rotations about the same axis commute (their products differ only by rounding)"""
    rng = np.random.default_rng(211)
    for index in range(10):
        axis = rng.normal(size=3)
        a, b = rng.uniform(-3.0, 3.0, 2)
        A, B = _about_axis(axis, a), _about_axis(axis, b)
        gap = np.max(np.abs(A @ B - B @ A))
        _expect_commutes(
            student,
            _commutes(student, A, B, Probe("matmul"), "commutes(A, B, matmul)"),
            f"said two rotations about one axis do not commute (pair #{index}, angles {a:.3f}, "
            f"{b:.3f}: A @ B - B @ A is {gap:.2g})",
            "compare max |op(a, b) - op(b, a)| with tol",
        )


@exercise("commutes", weight=3)
def test_commutes_random_rotations(student):
    """random pairs of rotations do not commute"""
    As, Bs = random_rotations(10, seed=212), random_rotations(10, seed=213)
    for index, (A, B) in enumerate(zip(As, Bs)):
        _expect_commutes(
            student,
            not _commutes(student, A, B, Probe("matmul"), "commutes(A, B, matmul)"),
            f"said a random pair of rotations commutes (pair #{index}: A @ B - B @ A is "
            f"{np.max(np.abs(A @ B - B @ A)):.2g})",
            "compare max |op(a, b) - op(b, a)| with tol",
        )


@exercise("commutes", weight=2)
def test_commutes_special_pairs(student):
    """half turns about perpendicular axes commute; R commutes with Rᵀ; quarter turns do not"""
    u = np.array([1.0, 2.0, 2.0]) / 3.0
    v = np.array([2.0, -2.0, 1.0]) / 3.0  # perpendicular to u
    _expect_commutes(
        student,
        _commutes(student, _about_axis(u, np.pi), _about_axis(v, np.pi), Probe("matmul"), "commutes"),
        "said two half turns about perpendicular axes do not commute",
        "their products agree up to rounding (~1e-15): compare max |op(a, b) - op(b, a)| with tol",
    )
    R = random_rotations(1, seed=214)[0]
    _expect_commutes(
        student,
        _commutes(student, R, R.T, Probe("matmul"), "commutes(R, Rᵀ)"),
        "said R and Rᵀ do not commute",
        "both products are I up to rounding: compare with tol",
    )
    _expect_commutes(
        student,
        not _commutes(student, _about_axis(u, np.pi / 2), _about_axis(v, np.pi / 2), Probe("matmul"), "commutes"),
        "said two quarter turns about perpendicular axes commute",
        "compare max |op(a, b) - op(b, a)| with tol",
    )


@exercise("commutes", weight=2)
def test_commutes_uses_op(student):
    """uses the op it is given: numbers, cross products, quaternions, addition"""
    try:
        numbers = _commutes(student, 2.5, -4.0, Probe("multiply"), "commutes(2.5, -4.0, multiply)")
    except StudentError as error:
        if error.kind != "exception":
            raise
        raise Wrong(f"commutes(2.5, -4.0, multiply): {error}", _commutes_slip(student) or "") from None
    general = "call op(a, b) and op(b, a) with the op argument and compare them within tol"
    _expect_commutes(student, numbers, "said 2.5 and -4.0 do not commute under multiplication", general)
    rng = np.random.default_rng(215)
    a, b = rng.normal(size=3), rng.normal(size=3)
    _expect_commutes(
        student,
        not _commutes(student, a, b, Probe("cross"), "commutes(a, b, cross)"),
        "said two random vectors commute under the cross product (a × b = -(b × a))",
        general,
    )
    _expect_commutes(
        student,
        _commutes(student, a, -2.0 * a, Probe("cross"), "commutes(a, -2a, cross)"),
        "said parallel vectors do not commute under the cross product (both products are 0)",
        general,
    )
    p, q = rng.normal(size=4), rng.normal(size=4)
    _expect_commutes(
        student,
        not _commutes(student, p, q, Probe("quat_multiply"), "commutes(p, q, quat_multiply)"),
        "said two random quaternions commute under the Hamilton product",
        general,
    )
    A, B = random_rotations(2, seed=216)
    _expect_commutes(
        student,
        _commutes(student, A, B, Probe("add"), "commutes(A, B, add)"),
        "said two matrices do not commute under addition",
        general,
    )


@exercise("commutes", weight=2)
def test_commutes_uses_tol(student):
    """uses tol: a commutator of ~3e-8 passes with tol=1e-5 and fails with tol=1e-9; a NaN never passes"""
    A = _about_axis([0.0, 0.0, 1.0], 0.3)
    B = Rotation.from_rotvec([1e-7, 0.0, 0.5]).as_matrix()
    gap = np.max(np.abs(A @ B - B @ A))
    _expect_commutes(
        student,
        _commutes(student, A, B, Probe("matmul"), "commutes(..., tol=1e-5)", tol=1e-5),
        f"with tol=1e-5 a difference of {gap:.2g} was not accepted",
        "compare with the tol argument",
    )
    _expect_commutes(
        student,
        not _commutes(student, A, B, Probe("matmul"), "commutes(..., tol=1e-9)", tol=1e-9),
        f"with tol=1e-9 a difference of {gap:.2g} was accepted",
        "compare with the tol argument",
    )
    expect(
        not _commutes(student, np.nan, 2.0, Probe("multiply"), "commutes(NaN, 2, ×)"),
        hints.COMMUTES_NAN_CAME_OUT_HINT,
        NAN_HINT,
    )


@exercise("commutes", weight=2)
def test_commutes_tol_is_absolute(student):
    """tol is absolute: dense matrices whose products (entries ~5) differ by ~1e-6 do not commute at tol=1e-9"""
    rng = np.random.default_rng(217)
    for index in range(3):
        M, N = rng.uniform(1.0, 2.0, (3, 3)), rng.normal(size=(3, 3))
        A, B = M, M + 1e-6 * N
        gap = np.max(np.abs(A @ B - B @ A))
        _expect_commutes(
            student,
            not _commutes(student, A, B, Probe("matmul"), "commutes(A, B, tol=1e-9)"),
            f"with tol=1e-9 said dense matrices commute whose products differ by {gap:.2g} (pair #{index})",
            "compare max |op(a, b) - op(b, a)| with tol, an absolute tolerance",
        )


@exercise("commutes", weight=2)
def test_commutes_tol_boundary(student):
    """tol is the largest accepted entry of |op(a, b) - op(b, a)|: two shears whose products differ by
    diag(2^-k, -2^-k) (exact in binary), at tol 0.1 % below, equal to and 0.1 % above 2^-k, k = 8 … 26"""
    for k in tolerance.GAP_EXPONENTS:
        A = np.eye(3)
        A[0, 1] = 2.0**-k
        B = np.eye(3)
        B[1, 0] = 1.0
        name = f"commutes(I + 2^-{k} e₁e₂ᵀ, I + e₂e₁ᵀ, @, tol)"
        problem = tolerance.boundary_problem(
            lambda tol: _commutes(student, A, B, Probe("matmul"), name, tol=tol),
            2.0**-k,
            "max |a @ b - b @ a|",
            name,
        )
        if problem:
            raise Wrong(*problem)
