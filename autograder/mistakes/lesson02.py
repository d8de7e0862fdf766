"""Typical mistakes for lesson 02: groups and SO(3)."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "group_closure_with_matmul",
        "check_group_axioms",
        "tests closure with the matrix product instead of the op it was given",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return bool(np.max(np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))) <= tol)
    closure = all(is_member(np.asarray(a) @ np.asarray(b)) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(
        equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(is_member(inverse(a)) and equal(op(a, inverse(a)), identity)
                       and equal(op(inverse(a), a), identity) for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c))) for a in samples for b in samples for c in samples)
    return {"closure": bool(closure), "identity": has_identity, "inverse": bool(has_inverses),
            "associativity": associative}
""",
        hint="@ instead of the op you are given",
        public_hint="@ instead of the op you are given",
    ),
    Mistake(
        "group_identity_one_sided",
        "check_group_axioms",
        "checks only identity ∘ a = a and a ∘ inverse(a) = e (one side each)",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return bool(np.max(np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))) <= tol)
    closure = all(is_member(op(a, b)) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(equal(op(identity, a), a) for a in samples)
    has_inverses = all(is_member(inverse(a)) and equal(op(a, inverse(a)), identity) for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c))) for a in samples for b in samples for c in samples)
    return {"closure": bool(closure), "identity": has_identity, "inverse": bool(has_inverses),
            "associativity": associative}
""",
        hint="op(a, identity) as well",
        public_hint="op(a, identity) as well",
    ),
    Mistake(
        "group_no_membership",
        "check_group_axioms",
        "never asks whether the identity and the inverses belong to the set",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return bool(np.max(np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))) <= tol)
    closure = all(is_member(op(a, b)) for a in samples for b in samples)
    has_identity = all(equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(equal(op(a, inverse(a)), identity) and equal(op(inverse(a), a), identity)
                       for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c))) for a in samples for b in samples for c in samples)
    return {"closure": bool(closure), "identity": has_identity, "inverse": has_inverses,
            "associativity": associative}
""",
        hint="is_member(identity)",
        public_hint="is_member(identity)",
    ),
    Mistake(
        "group_associativity_assumed",
        "check_group_axioms",
        "assumes associativity always holds instead of testing the triples",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return bool(np.max(np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))) <= tol)
    closure = all(is_member(op(a, b)) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(
        equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(is_member(inverse(a)) and equal(op(a, inverse(a)), identity)
                       and equal(op(inverse(a), a), identity) for a in samples)
    return {"closure": bool(closure), "identity": has_identity, "inverse": bool(has_inverses),
            "associativity": True}
""",
        hint="every ordered triple",
        public_hint="every ordered triple",
    ),
    Mistake(
        "group_allclose_rtol",
        "check_group_axioms",
        "compares with np.allclose(atol=tol), whose default rtol=1e-5 swamps tol",
        hint="rtol=1e-5",
        public_hint="rtol=1e-5",
        source="""
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return bool(np.allclose(x, y, atol=tol))
    closure = all(is_member(op(a, b)) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(
        equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(is_member(inverse(a)) and equal(op(a, inverse(a)), identity)
                       and equal(op(inverse(a), a), identity) for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c))) for a in samples for b in samples for c in samples)
    return {"closure": bool(closure), "identity": has_identity, "inverse": bool(has_inverses),
            "associativity": associative}
""",
    ),
    Mistake(
        "group_exact_equality",
        "check_group_axioms",
        "compares with == instead of within tol",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return bool(np.all(np.asarray(x) == np.asarray(y)))
    closure = all(is_member(op(a, b)) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(
        equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(is_member(inverse(a)) and equal(op(a, inverse(a)), identity)
                       and equal(op(inverse(a), a), identity) for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c))) for a in samples for b in samples for c in samples)
    return {"closure": bool(closure), "identity": has_identity, "inverse": bool(has_inverses),
            "associativity": associative}
""",
        hint="differ by rounding",
        public_hint="never with ==",
        classic=True,
    ),
    Mistake(
        "group_scalar_equality",
        "check_group_axioms",
        "compares elements as if they were numbers, abs(x - y) <= tol: crashes on matrices",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        return abs(x - y) <= tol
    closure = all(is_member(op(a, b)) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(
        equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(is_member(inverse(a)) and equal(op(a, inverse(a)), identity)
                       and equal(op(inverse(a), a), identity) for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c))) for a in samples for b in samples for c in samples)
    return {"closure": bool(closure), "identity": bool(has_identity), "inverse": bool(has_inverses),
            "associativity": bool(associative)}
""",
        hint="reduce it to one verdict first",
        public_hint="reduce it to one verdict first",
    ),
    Mistake(
        "commutes_exact_equality",
        "commutes",
        "compares the two products with exact equality",
        """
def commutes(a, b, op, tol=1e-9):
    return bool(np.array_equal(op(a, b), op(b, a)))
""",
        hint="never with ==",
        public_hint="never with ==",
        classic=True,
    ),
    Mistake(
        "commutes_allclose_rtol",
        "commutes",
        "np.allclose(op(a, b), op(b, a), atol=tol): rtol hides 1e-6",
        """
def commutes(a, b, op, tol=1e-9):
    return bool(np.allclose(op(a, b), op(b, a), atol=tol))
""",
        hint="rtol=1e-5",
        public_hint="rtol=1e-5",
    ),
    Mistake(
        "commutes_fixed_tol",
        "commutes",
        "ignores tol and uses 1e-6",
        """
def commutes(a, b, op, tol=1e-9):
    return bool(np.max(np.abs(np.asarray(op(a, b)) - np.asarray(op(b, a)))) <= 1e-6)
""",
        hint="does not change with tol",
        public_hint="does not change with tol",
    ),
    Mistake(
        "commutes_ignores_op",
        "commutes",
        "always uses the matrix product instead of op",
        """
def commutes(a, b, op, tol=1e-9):
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return bool(np.max(np.abs(a @ b - b @ a)) <= tol)
""",
        hint="whatever op is given",
        public_hint="whatever op is given",
    ),
    Mistake(
        "commutes_same_order",
        "commutes",
        "compares op(a, b) with itself (arguments never swapped)",
        """
def commutes(a, b, op, tol=1e-9):
    return bool(np.max(np.abs(np.asarray(op(a, b)) - np.asarray(op(a, b)))) <= tol)
""",
        hint="swap the arguments",
        public_hint="swap the arguments",
    ),
    Mistake(
        "commutes_frobenius_norm",
        "commutes",
        "compares the Frobenius norm of op(a, b) - op(b, a) with tol, not its largest entry (tol read another way)",
        """
def commutes(a, b, op, tol=1e-9):
    difference = np.asarray(op(a, b), dtype=float) - np.asarray(op(b, a), dtype=float)
    return bool(np.linalg.norm(difference) <= tol)
""",
        hint="equal to tol must pass",
        public_hint="equal to tol must pass",
    ),
    Mistake(
        "check_group_axioms_half_tol",
        "check_group_axioms",
        'accepts only differences below tol / 2 ("within tol either side" read as a band of width tol)',
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    def equal(x, y):
        difference = np.abs(np.asarray(x, dtype=float) - np.asarray(y, dtype=float))
        return bool(difference.size == 0 or np.max(difference) <= tol / 2)

    closure = all(bool(is_member(op(a, b))) for a in samples for b in samples)
    has_identity = bool(is_member(identity)) and all(
        equal(op(identity, a), a) and equal(op(a, identity), a) for a in samples)
    has_inverses = all(
        bool(is_member(inverse(a))) and equal(op(a, inverse(a)), identity) and equal(op(inverse(a), a), identity)
        for a in samples)
    associative = all(equal(op(op(a, b), c), op(a, op(b, c)))
                      for a in samples for b in samples for c in samples)
    return {"closure": closure, "identity": has_identity, "inverse": has_inverses, "associativity": associative}
""",
        hint="equal to tol must pass",
        public_hint="equal to tol must pass",
    ),
]

ALTERNATIVES = [
    Alternative(
        "group_axioms_itertools",
        "check_group_axioms",
        "itertools.product and allclose with rtol=0",
        """
def check_group_axioms(samples, op, identity, inverse, is_member, tol=1e-9):
    from itertools import product

    def same(x, y):
        x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
        return bool(np.all(np.isfinite(x)) and np.allclose(x, y, rtol=0.0, atol=tol))

    result = {"closure": all(bool(is_member(op(a, b))) for a, b in product(samples, repeat=2))}
    result["identity"] = bool(is_member(identity)) and all(
        same(op(identity, a), a) and same(op(a, identity), a) for a in samples)
    result["inverse"] = all(bool(is_member(inverse(a))) and same(op(a, inverse(a)), identity)
                            and same(op(inverse(a), a), identity) for a in samples)
    result["associativity"] = all(same(op(op(a, b), c), op(a, op(b, c))) for a, b, c in product(samples, repeat=3))
    return result
""",
    ),
    Alternative(
        "commutes_allclose_rtol0",
        "commutes",
        "np.allclose with rtol=0, returns a numpy bool",
        """
def commutes(a, b, op, tol=1e-9):
    return np.allclose(op(a, b), op(b, a), rtol=0.0, atol=tol)
""",
    ),
]

SAMPLE = {
    "farid": ["group_no_membership"],  # lets -R and the zero matrix through, as he lets reflections through
}
