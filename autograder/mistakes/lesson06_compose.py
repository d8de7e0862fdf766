"""Typical mistakes and correct alternatives for lesson 06, section 10: the Jacobians of composition and inversion."""

from . import Alternative, Mistake

MISTAKES = [
    # ------------------------------------------------------------ jacobians_of_compose
    Mistake(
        "compose_transposed",
        "jacobians_of_compose",
        "J1 = R2 instead of its transpose",
        """
def jacobians_of_compose(R1, R2):
    return np.asarray(R2, dtype=float), np.eye(3)
""",
        hint="the transpose of what finite differences give",
        public_hint="the transpose of what finite differences give",
        classic=True,
    ),
    Mistake(
        "compose_identity",
        "jacobians_of_compose",
        "J1 = J2 = I: ignores the factor the turn crosses",
        """
def jacobians_of_compose(R1, R2):
    return np.eye(3), np.eye(3)
""",
        hint="your J1 fits only when R2 = I",
        public_hint="your J1 fits only when R2 = I",
    ),
    Mistake(
        "compose_left",
        "jacobians_of_compose",
        "the left Jacobians (I, R1)",
        """
def jacobians_of_compose(R1, R2):
    return np.eye(3), np.asarray(R1, dtype=float)
""",
        hint="left Jacobians",
        public_hint="left Jacobians",
    ),
    Mistake(
        "compose_swapped",
        "jacobians_of_compose",
        "returns (J2, J1)",
        """
def jacobians_of_compose(R1, R2):
    return np.eye(3), np.asarray(R2, dtype=float).T
""",
        hint="swapped",
        public_hint="swapped",
    ),
    Mistake(
        "compose_wrong_factor",
        "jacobians_of_compose",
        "J1 = R1ᵀ: the transpose of the wrong factor",
        """
def jacobians_of_compose(R1, R2):
    return np.asarray(R1, dtype=float).T, np.eye(3)
""",
        hint="fits the product taken the other way round",
        public_hint="fits the product taken the other way round",
    ),
    Mistake(
        "compose_jacobian_float32",
        "jacobians_of_compose",
        "the right J1 stored in float32",
        """
def jacobians_of_compose(R1, R2):
    return np.asarray(R2, dtype=np.float32).T, np.eye(3)
""",
        hint="float32 rounding",
        public_hint="float32 rounding",
    ),
    # ------------------------------------------------------------ jacobian_of_inverse
    Mistake(
        "inverse_left",
        "jacobian_of_inverse",
        "-Rᵀ: the Jacobian of the left perturbations",
        """
def jacobian_of_inverse(R):
    return -np.asarray(R, dtype=float).T
""",
        hint="perturbations on the left of R and of R⁻¹",
        public_hint="perturbations on the left of R and of R⁻¹",
        classic=True,
    ),
    Mistake(
        "inverse_not_moved",
        "jacobian_of_inverse",
        "-I: the reversed turn left on the left of Rᵀ",
        """
def jacobian_of_inverse(R):
    return -np.eye(3)
""",
        hint="your J does not change with R",
        public_hint="your J does not change with R",
    ),
    Mistake(
        "inverse_sign",
        "jacobian_of_inverse",
        "+R: the sign of the inverted turn lost",
        """
def jacobian_of_inverse(R):
    return np.asarray(R, dtype=float).copy()
""",
        hint="must undo that small turn",
        public_hint="must undo that small turn",
    ),
    Mistake(
        "inverse_transpose",
        "jacobian_of_inverse",
        "Rᵀ: the inverse of R instead of its Jacobian",
        """
def jacobian_of_inverse(R):
    return np.asarray(R, dtype=float).T.copy()
""",
        hint="wrong in two ways at once",
        public_hint="wrong in two ways at once",
    ),
    Mistake(
        "inverse_jacobian_float32",
        "jacobian_of_inverse",
        "the right J stored in float32",
        """
def jacobian_of_inverse(R):
    return -np.asarray(R, dtype=np.float32)
""",
        hint="float32 rounding",
        public_hint="float32 rounding",
    ),
    Mistake(
        "compose_jacobians_lists_transposed",
        "jacobians_of_compose",
        "R2.T on the input as given: a list has no .T",
        """
def jacobians_of_compose(R1, R2):
    return R2.T, np.eye(3)
""",
        hint="the conventions admit nested lists",
        public_hint="convert the inputs with np.asarray(..., dtype=float)",
    ),
]

ALTERNATIVES = [
    Alternative(
        "compose_by_inverse",
        "jacobians_of_compose",
        "J1 = inv(R2)",
        """
def jacobians_of_compose(R1, R2):
    return np.linalg.inv(np.asarray(R2, dtype=float)), np.identity(3)
""",
    ),
    Alternative(
        "compose_by_conjugating_generators",
        "jacobians_of_compose",
        "column j of J1 read off R2ᵀ [e_j]× R2",
        """
def jacobians_of_compose(R1, R2):
    R2 = np.asarray(R2, dtype=float)
    columns = []
    for e in np.eye(3):
        M = R2.T @ skew(e) @ R2                 # the generator e_j, conjugated across R2
        columns.append([M[2, 1], M[0, 2], M[1, 0]])
    return np.column_stack(columns), np.eye(3)
""",
    ),
    Alternative(
        "inverse_by_adjoint",
        "jacobian_of_inverse",
        "minus the adjoint of R, built from its columns",
        """
def jacobian_of_inverse(R):
    R = np.asarray(R, dtype=float)
    return -np.column_stack([R @ e for e in np.eye(3)])
""",
    ),
]
