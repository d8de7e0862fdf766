"""Typical mistakes for lesson 04, section 15: the shortest rotation between two directions."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "two_vectors_full_angle",
        "quat_from_two_vectors",
        "[cos θ, sin θ u]: the full angle",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float) / np.linalg.norm(a)
    b = np.asarray(b, dtype=float) / np.linalg.norm(b)
    axis = np.cross(a, b)
    axis = axis - (axis @ a) * a
    s = np.linalg.norm(axis)
    if s < 1e-14:
        if a @ b > 0.0:
            return np.array([1.0, 0.0, 0.0, 0.0])
        axis = np.cross(a, np.eye(3)[int(np.argmin(np.abs(a)))])
        return np.concatenate([[0.0], axis / np.linalg.norm(axis)])
    theta = np.arctan2(s, a @ b)
    return np.concatenate([[np.cos(theta)], np.sin(theta) * axis / s])
""",
        hint="holds half the angle",
        public_hint="holds half the angle",
        classic=True,
    ),
    Mistake(
        "two_vectors_reversed_axis",
        "quat_from_two_vectors",
        "axis along b × a: the opposite turn",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float) / np.linalg.norm(a)
    b = np.asarray(b, dtype=float) / np.linalg.norm(b)
    axis = np.cross(b, a)
    axis = axis - (axis @ a) * a
    s = np.linalg.norm(axis)
    if s < 1e-14:
        if a @ b > 0.0:
            return np.array([1.0, 0.0, 0.0, 0.0])
        axis = np.cross(a, np.eye(3)[int(np.argmin(np.abs(a)))])
        return np.concatenate([[0.0], axis / np.linalg.norm(axis)])
    theta = np.arctan2(s, a @ b)
    return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * axis / s])
""",
        hint="the axis points the wrong way",
        public_hint="the axis points the wrong way",
    ),
    Mistake(
        "two_vectors_unnormalised",
        "quat_from_two_vectors",
        "[1 + a·b, a × b] without normalising a and b",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    q = np.concatenate([[1.0 + a @ b], np.cross(a, b)])
    return q / np.linalg.norm(q)
""",
        hint="normalise a and b first",
        public_hint="normalise a and b first",
    ),
    Mistake(
        "two_vectors_arccos",
        "quat_from_two_vectors",
        "θ = arccos(a · b): tiny angles lost",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float) / np.linalg.norm(a)
    b = np.asarray(b, dtype=float) / np.linalg.norm(b)
    axis = np.cross(a, b)
    axis = axis - (axis @ a) * a
    s = np.linalg.norm(axis)
    if s < 1e-14:
        if a @ b > 0.0:
            return np.array([1.0, 0.0, 0.0, 0.0])
        axis = np.cross(a, np.eye(3)[int(np.argmin(np.abs(a)))])
        return np.concatenate([[0.0], axis / np.linalg.norm(axis)])
    theta = np.arccos(np.clip(a @ b, -1.0, 1.0))
    return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * axis / s])
""",
        hint="arccos loses small angles",
        public_hint="arccos loses small angles",
    ),
    Mistake(
        "two_vectors_opposite_nan",
        "quat_from_two_vectors",
        "no axis for opposite directions: NaN",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float) / np.linalg.norm(a)
    b = np.asarray(b, dtype=float) / np.linalg.norm(b)
    axis = np.cross(a, b)
    s = np.linalg.norm(axis)
    if s == 0.0 and a @ b > 0.0:
        return np.array([1.0, 0.0, 0.0, 0.0])
    theta = np.arctan2(s, a @ b)
    return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * axis / s])
""",
        hint="take a half turn about any axis perpendicular to a",
        public_hint="take a half turn about any axis",
    ),
    Mistake(
        "two_vectors_threshold_on_raw_b",
        "quat_from_two_vectors",
        "normalises a only: the parallel test |a × b| < 1e-14 then depends on the length of b",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float)
    b = np.asarray(b, dtype=float)
    a = a / np.linalg.norm(a)
    axis = np.cross(a, b)
    axis = axis - (axis @ a) * a
    s = np.linalg.norm(axis)
    if s < 1e-14:
        if a @ b > 0.0:
            return np.array([1.0, 0.0, 0.0, 0.0])
        helper = np.eye(3)[int(np.argmin(np.abs(a)))]
        axis = np.cross(a, helper)
        return np.concatenate([[0.0], axis / np.linalg.norm(axis)])
    theta = np.arctan2(s, a @ b)
    return np.concatenate([[np.cos(theta / 2.0)], np.sin(theta / 2.0) * axis / s])
""",
        hint="normalise a and b first",
        public_hint="normalise a and b first",
    ),
]

ALTERNATIVES = [
    Alternative(
        "two_vectors_textbook",
        "quat_from_two_vectors",
        "normalise [1 + a·b, a × b]; a half turn when opposite",
        """
def quat_from_two_vectors(a, b):
    a = np.asarray(a, dtype=float) / np.linalg.norm(a)
    b = np.asarray(b, dtype=float) / np.linalg.norm(b)
    q = np.concatenate([[1.0 + a @ b], np.cross(a, b)])     # 2 cos(θ/2) [cos(θ/2), sin(θ/2) u]
    if np.linalg.norm(q) < 1e-7:                            # within 1e-7 rad of opposite: q is rounding noise
        axis = np.cross(a, np.eye(3)[int(np.argmin(np.abs(a)))])
        return np.concatenate([[0.0], axis / np.linalg.norm(axis)])
    return q / np.linalg.norm(q)
""",
    ),
]
