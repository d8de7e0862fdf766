"""Typical mistakes for lesson 03, section 8: body and world angular velocity."""

from . import Alternative, Mistake

_VEE = "0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]])"

MISTAKES = [
    Mistake(
        "body_rate_is_world_rate",
        "body_angular_velocity",
        "returns the world rate vee(Ṙ Rᵀ)",
        f"""
def body_angular_velocity(R, R_dot):
    W = np.asarray(R_dot, dtype=float) @ np.asarray(R, dtype=float).T
    return {_VEE}
""",
        hint="that is the world rate",
        public_hint="that is the world rate",
        classic=True,
    ),
    Mistake(
        "body_rate_sign",
        "body_angular_velocity",
        "vee(Ṙᵀ R): the opposite spin",
        f"""
def body_angular_velocity(R, R_dot):
    W = np.asarray(R_dot, dtype=float).T @ np.asarray(R, dtype=float)
    return {_VEE}
""",
        hint="the opposite spin",
        public_hint="the opposite spin",
    ),
    Mistake(
        "body_rate_ignores_R",
        "body_angular_velocity",
        "vee(Ṙ): reads the rate off Ṙ itself",
        f"""
def body_angular_velocity(R, R_dot):
    W = np.asarray(R_dot, dtype=float)
    return {_VEE}
""",
        hint="Ṙ alone is not skew-symmetric",
        public_hint="Ṙ alone is not skew-symmetric",
    ),
    Mistake(
        "body_rate_turned_twice",
        "body_angular_velocity",
        "Rᵀ vee(Rᵀ Ṙ): into body axes twice",
        f"""
def body_angular_velocity(R, R_dot):
    R = np.asarray(R, dtype=float)
    W = R.T @ np.asarray(R_dot, dtype=float)
    return R.T @ ({_VEE})
""",
        hint="one change of axes too many",
        public_hint="one change of axes too many",
    ),
    Mistake(
        "body_rate_lists_transposed",
        "body_angular_velocity",
        "R.T @ R_dot on the inputs as given: plain lists have no .T",
        """
def body_angular_velocity(R, R_dot):
    W = R.T @ R_dot
    return 0.5 * np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]])
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "body_rate_from_world_rate",
        "body_angular_velocity",
        "ω_w = vee(Ṙ Rᵀ), then ω_b = Rᵀ ω_w",
        """
def body_angular_velocity(R, R_dot):
    R = np.asarray(R, dtype=float)
    W = np.asarray(R_dot, dtype=float) @ R.T
    omega_w = np.array([W[2, 1], W[0, 2], W[1, 0]])
    return R.T @ omega_w
""",
    ),
]

SAMPLE = {"dev": ["body_rate_is_world_rate"]}
