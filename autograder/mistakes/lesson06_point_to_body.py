"""Typical mistakes for lesson 06, section 9: the Jacobian of a world point seen from the body."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "point_to_body_left",
        "jacobian_point_to_body",
        "Rᵀ [p_w]×: the left-perturbation Jacobian",
        """
def jacobian_point_to_body(R, p_w):
    return np.asarray(R, dtype=float).T @ skew(p_w)
""",
        hint="belongs to the left perturbation",
        public_hint="belongs to the left perturbation",
        classic=True,
    ),
    Mistake(
        "point_to_body_sign",
        "jacobian_point_to_body",
        "-[Rᵀ p_w]×: the sign of Exp(-δ) lost",
        """
def jacobian_point_to_body(R, p_w):
    return -skew(np.asarray(R, dtype=float).T @ np.asarray(p_w, dtype=float))
""",
        hint="the sign is flipped: J is the negative",
        public_hint="the sign is flipped: J is the negative",
    ),
    Mistake(
        "point_to_body_no_R",
        "jacobian_point_to_body",
        "[p_w]×: forgets the attitude",
        """
def jacobian_point_to_body(R, p_w):
    return skew(p_w)
""",
        hint="fits the finite differences only at the identity attitude",
        public_hint="fits the finite differences only at the identity attitude",
    ),
    Mistake(
        "point_to_body_forward",
        "jacobian_point_to_body",
        "-R [p]×: section 6's Jacobian copied",
        """
def jacobian_point_to_body(R, p_w):
    return -np.asarray(R, dtype=float) @ skew(p_w)
""",
        hint="is the Jacobian of R p (body to world)",
        public_hint="is the Jacobian of R p (body to world)",
    ),
    Mistake(
        "point_to_body_lists_transposed",
        "jacobian_point_to_body",
        "R.T @ p_w on the inputs as given: plain lists have no .T",
        """
def jacobian_point_to_body(R, p_w):
    return skew(R.T @ p_w)
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "point_to_body_conjugated",
        "jacobian_point_to_body",
        "Rᵀ [p_w]× R, the same matrix by the adjoint",
        """
def jacobian_point_to_body(R, p_w):
    R = np.asarray(R, dtype=float)
    return R.T @ skew(p_w) @ R
""",
    ),
]
