"""Typical mistakes and correct alternatives for lesson 04, section 14: the power of a unit quaternion."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "power_full_angle",
        "quat_power",
        "[cos 2tα, sin 2tα u]: the full rotation angle in place of α",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    s = np.linalg.norm(q[1:])
    theta = 2.0 * np.arctan2(s, q[0])
    axis = q[1:] / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * theta)], np.sin(t * theta) * axis])
""",
        hint="how the half angle enters q",
        public_hint="how the half angle enters q",
    ),
    Mistake(
        "power_arccos",
        "quat_power",
        "α = arccos(w): small angles are lost",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    s = np.linalg.norm(q[1:])
    alpha = np.arccos(np.clip(q[0], -1.0, 1.0))
    axis = q[1:] / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * axis])
""",
        hint="arccos(w) rounds small half-angles",
        public_hint="arccos(w) rounds small half-angles",
        classic=True,
    ),
    Mistake(
        "power_canonical_sign",
        "quat_power",
        "flips q to w >= 0 first (q and -q get one power)",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    if q[0] < 0.0:
        q = -q
    s = np.linalg.norm(q[1:])
    alpha = np.arctan2(s, q[0])
    axis = q[1:] / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * axis])
""",
        hint="do not flip the sign of q",
        public_hint="do not flip the sign of q",
    ),
    Mistake(
        "power_axis_not_unit",
        "quat_power",
        "uses v = sin α u as the axis",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    alpha = np.arctan2(np.linalg.norm(q[1:]), q[0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * q[1:]])
""",
        hint="is not a unit vector",
        public_hint="is not a unit vector",
    ),
    Mistake(
        "power_identity_nan",
        "quat_power",
        "divides by |v| = 0 at the identity",
        """
def quat_power(q, t):
    q = np.asarray(q, dtype=float)
    s = np.linalg.norm(q[1:])
    alpha = np.arctan2(s, q[0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * q[1:] / s])
""",
        hint="guard the division",
        public_hint="guard the division",
    ),
    Mistake(
        "quat_power_lists_sliced",
        "quat_power",
        "q[1:] of the input as given: v @ v does not work on a list",
        """
def quat_power(q, t):
    w, v = q[0], q[1:]
    s = np.sqrt(v @ v)
    alpha = np.arctan2(s, w)
    axis = v / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[np.cos(t * alpha)], np.sin(t * alpha) * axis])
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="unsupported operand type(s) for @: 'list' and 'list'",
    ),
]

ALTERNATIVES = [
    Alternative(
        "power_by_complex_numbers",
        "quat_power",
        "w + i|v| raised to t with Python's complex power",
        """
def quat_power(q, t):
    w, x, y, z = np.asarray(q, dtype=float)
    s = np.sqrt(x * x + y * y + z * z)
    power = complex(w, s) ** t              # the principal branch: the angle of w + i s is α in [0, π]
    axis = np.array([x, y, z]) / s if s > 0.0 else np.array([1.0, 0.0, 0.0])
    return np.concatenate([[power.real], power.imag * axis])
""",
    ),
    Alternative(
        "power_by_exp_and_log",
        "quat_power",
        "Exp_q(t Log_q q) written as two helpers, the log with a list result",
        """
def quat_power(q, t):
    def log_q(q):
        w, v = q[0], np.asarray(q[1:], dtype=float)
        s = np.linalg.norm(v)
        if s == 0.0:
            return [0.0, 0.0, 0.0] if w > 0 else [2.0 * np.pi, 0.0, 0.0]
        return list(2.0 * np.arctan2(s, w) * v / s)

    def exp_q(theta_vector):
        theta_vector = np.asarray(theta_vector, dtype=float)
        theta = np.linalg.norm(theta_vector)
        if theta == 0.0:
            return np.array([1.0, 0.0, 0.0, 0.0])
        return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * theta_vector / theta])

    return exp_q(t * np.asarray(log_q(list(q))))
""",
    ),
]
