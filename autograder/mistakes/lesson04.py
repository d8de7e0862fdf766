"""Typical mistakes for lesson 04: quaternions."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "quat_multiply_cross_flipped",
        "quat_multiply",
        "cross product with the wrong sign (the JPL product, ij = -k)",
        """
def quat_multiply(p, q):
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    w = p[0] * q[0] - p[1:] @ q[1:]
    v = p[0] * q[1:] + q[0] * p[1:] - np.cross(p[1:], q[1:])
    return np.concatenate([[w], v])
""",
        hint="JPL",
        public_hint="JPL",
        classic=True,
    ),
    Mistake(
        "quat_left_transposed",
        "quat_left",
        "typed [q]_L with rows and columns swapped",
        """
def quat_left(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, x, y, z],
                     [-x, w, z, -y],
                     [-y, -z, w, x],
                     [-z, y, -x, w]])
""",
        hint="transpose of [p]_L",
        public_hint="transpose of [q]_L",
    ),
    Mistake(
        "quat_right_wrong_cross_sign",
        "quat_right",
        "[q]_R with +[v]× (a copy of [q]_L)",
        """
def quat_right(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z],
                     [x, w, -z, y],
                     [y, z, w, -x],
                     [z, -y, x, w]])
""",
        hint="this is [q]_L",
        public_hint="this is [q]_L",
    ),
    Mistake(
        "quat_conjugate_negates_scalar",
        "quat_conjugate",
        "negates the scalar part instead of the vector",
        """
def quat_conjugate(q):
    q = np.array(q, dtype=float)
    q[0] = -q[0]
    return q
""",
        hint="negated the scalar",
        public_hint="the result is -q*",
    ),
    Mistake(
        "quat_inverse_no_norm",
        "quat_inverse",
        "returns the conjugate without dividing by |q|²",
        """
def quat_inverse(q):
    q = np.asarray(q, dtype=float)
    return np.array([q[0], -q[1], -q[2], -q[3]])
""",
        hint="returned the conjugate",
        public_hint="returned the conjugate",
    ),
    Mistake(
        "quat_inverse_floor_on_norm",
        "quat_inverse",
        "guards |q|² with a floor of 1e-12, so a short quaternion's inverse is far too small",
        """
def quat_inverse(q):
    q = np.asarray(q, dtype=float)
    return np.array([q[0], -q[1], -q[2], -q[3]]) / max(q @ q, 1e-12)
""",
        hint="needs a floor on |q|²",
        public_hint="needs a floor on |q|²",
    ),
    Mistake(
        "quat_from_axis_angle_full_angle",
        "quat_from_axis_angle",
        "uses θ instead of θ/2",
        """
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    return np.concatenate([[np.cos(theta)], np.sin(theta) * u])
""",
        hint="half angle",
        public_hint="half angle",
        classic=True,
    ),
    Mistake(
        "quat_from_axis_angle_degrees",
        "quat_from_axis_angle",
        "treats the angle as degrees",
        """
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    half = np.radians(theta) / 2
    return np.concatenate([[np.cos(half)], np.sin(half) * u])
""",
        hint="degrees",
        public_hint="degrees",
    ),
    Mistake(
        "quat_rotate_conjugate_left",
        "quat_rotate",
        "q* ⊗ v ⊗ q: rotates the opposite way",
        """
def quat_rotate(q, v):
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]],
                               a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    q = np.asarray(q, dtype=float)
    q_conj = np.concatenate([q[:1], -q[1:]])
    return mul(mul(q_conj, np.concatenate([[0.0], v])), q)[1:]
""",
        hint="opposite way",
        public_hint="opposite way",
    ),
    Mistake(
        "quat_to_matrix_transposed",
        "quat_to_matrix",
        "the 2w[v]× terms with the wrong sign (the transpose)",
        """
def quat_to_matrix(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
                     [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
                     [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]])
""",
        hint="transpose",
        public_hint="transpose",
    ),
    Mistake(
        "quat_to_matrix_scalar_last",
        "quat_to_matrix",
        "reads q as scalar last [x, y, z, w]",
        """
def quat_to_matrix(q):
    x, y, z, w = np.asarray(q, dtype=float)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
""",
        hint="scalar last",
        public_hint="scalar last",
    ),
    Mistake(
        "matrix_to_quat_naive",
        "matrix_to_quat",
        "w = √(1 + tr R)/2, then divide by 4w: fails near π",
        """
def matrix_to_quat(R):
    R = np.asarray(R, dtype=float)
    w = 0.5 * np.sqrt(1.0 + np.trace(R))
    x = (R[2, 1] - R[1, 2]) / (4 * w)
    y = (R[0, 2] - R[2, 0]) / (4 * w)
    z = (R[1, 0] - R[0, 1]) / (4 * w)
    return np.array([w, x, y, z])
""",
        hint="cannot be small",
        public_hint="dividing by 4w fails",
    ),
    Mistake(
        "matrix_to_quat_no_canonical",
        "matrix_to_quat",
        "Shepperd's branches but w < 0 is not flipped",
        """
def matrix_to_quat(R):
    R = np.asarray(R, dtype=float)
    t = np.trace(R)
    k = int(np.argmax([t, R[0, 0], R[1, 1], R[2, 2]]))
    if k == 0:
        w = 0.5 * np.sqrt(1.0 + t)
        q = np.array([w, (R[2, 1] - R[1, 2]) / (4 * w), (R[0, 2] - R[2, 0]) / (4 * w), (R[1, 0] - R[0, 1]) / (4 * w)])
    elif k == 1:
        x = 0.5 * np.sqrt(1.0 + 2 * R[0, 0] - t)
        q = np.array([(R[2, 1] - R[1, 2]) / (4 * x), x, (R[0, 1] + R[1, 0]) / (4 * x), (R[0, 2] + R[2, 0]) / (4 * x)])
    elif k == 2:
        y = 0.5 * np.sqrt(1.0 + 2 * R[1, 1] - t)
        q = np.array([(R[0, 2] - R[2, 0]) / (4 * y), (R[0, 1] + R[1, 0]) / (4 * y), y, (R[1, 2] + R[2, 1]) / (4 * y)])
    else:
        z = 0.5 * np.sqrt(1.0 + 2 * R[2, 2] - t)
        q = np.array([(R[1, 0] - R[0, 1]) / (4 * z), (R[0, 2] + R[2, 0]) / (4 * z), (R[1, 2] + R[2, 1]) / (4 * z), z])
    return q / np.linalg.norm(q)
""",
        hint="canonical choice",
        public_hint="canonical sign",
        classic=True,
    ),
    Mistake(
        "wxyz_to_xyzw_reversed",
        "wxyz_to_xyzw",
        "reverses the array ([z, y, x, w])",
        """
def wxyz_to_xyzw(q):
    return np.asarray(q, dtype=float)[..., ::-1]
""",
        hint="reversed",
        public_hint="reversed",
    ),
    Mistake(
        "xyzw_to_wxyz_wrong_roll",
        "xyzw_to_wxyz",
        "rolls the wrong way ([y, z, w, x])",
        """
def xyzw_to_wxyz(q):
    return np.roll(np.asarray(q, dtype=float), -1, axis=-1)
""",
        hint="wrong way",
        public_hint="wrong way",
    ),
    Mistake(
        "quat_slerp_long_arc",
        "quat_slerp",
        "no sign flip when q0 · q1 < 0: the longer arc",
        """
def quat_slerp(q0, q1, t):
    q0 = np.asarray(q0, dtype=float)
    q1 = np.asarray(q1, dtype=float)
    omega = np.arccos(np.clip(q0 @ q1, -1.0, 1.0))
    if np.sin(omega) < 1e-12:
        return q0.copy()
    return (np.sin((1 - t) * omega) * q0 + np.sin(t * omega) * q1) / np.sin(omega)
""",
        hint="longer arc",
        public_hint="longer arc",
    ),
    Mistake(
        "quat_slerp_linear",
        "quat_slerp",
        "plain linear interpolation, not normalised",
        """
def quat_slerp(q0, q1, t):
    q0 = np.asarray(q0, dtype=float)
    q1 = np.asarray(q1, dtype=float)
    if q0 @ q1 < 0:
        q1 = -q1
    return (1 - t) * q0 + t * q1
""",
        hint="plain linear",
        public_hint="plain linear",
    ),
    Mistake(
        "quat_multiply_no_cross",
        "quat_multiply",
        "drops the cross product p_v × q_v",
        """
def quat_multiply(p, q):
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    return np.concatenate([[p[0] * q[0] - p[1:] @ q[1:]], p[0] * q[1:] + q[0] * p[1:]])
""",
        hint="cross product is missing",
        public_hint="cross product is missing",
    ),
    Mistake(
        "quat_multiply_dot_plus",
        "quat_multiply",
        "w = p_w q_w + p_v · q_v (wrong sign of the dot product)",
        """
def quat_multiply(p, q):
    p, q = np.asarray(p, dtype=float), np.asarray(q, dtype=float)
    return np.concatenate([[p[0] * q[0] + p[1:] @ q[1:]], p[0] * q[1:] + q[0] * p[1:] + np.cross(p[1:], q[1:])])
""",
        hint="minus the dot product",
        public_hint="minus the dot product",
    ),
    Mistake(
        "quat_multiply_elementwise",
        "quat_multiply",
        "p * q entry by entry",
        """
def quat_multiply(p, q):
    return np.asarray(p, dtype=float) * np.asarray(q, dtype=float)
""",
        hint="entry by entry",
        public_hint="entry by entry",
    ),
    Mistake(
        "quat_left_is_right",
        "quat_left",
        "returns the right-product matrix [q]_R",
        """
def quat_left(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z], [x, w, z, -y], [y, -z, w, x], [z, y, -x, w]])
""",
        hint="this is [p]_R",
        public_hint="this is [q]_R",
    ),
    Mistake(
        "quat_left_no_minus_row",
        "quat_left",
        "first row [w, x, y, z] without the minus signs",
        """
def quat_left(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, x, y, z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])
""",
        hint="minus signs are missing",
        public_hint="minus signs are missing",
    ),
    Mistake(
        "quat_left_scalar_last",
        "quat_left",
        "reads q as [x, y, z, w]",
        """
def quat_left(q):
    x, y, z, w = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])
""",
        hint="scalar last",
        public_hint="scalar last",
    ),
    Mistake(
        "quat_right_is_left",
        "quat_right",
        "returns the left-product matrix [q]_L",
        """
def quat_right(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])
""",
        hint="this is [q]_L",
        public_hint="this is [q]_L",
    ),
    Mistake(
        "quat_right_transposed",
        "quat_right",
        "[q]_R with rows and columns swapped",
        """
def quat_right(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z], [x, w, z, -y], [y, -z, w, x], [z, y, -x, w]]).T
""",
        hint="transpose of [q]_R",
        public_hint="transpose of [q]_R",
    ),
    Mistake(
        "quat_right_scalar_last",
        "quat_right",
        "reads q as [x, y, z, w]",
        """
def quat_right(q):
    x, y, z, w = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z], [x, w, z, -y], [y, -z, w, x], [z, y, -x, w]])
""",
        hint="scalar last",
        public_hint="scalar last",
    ),
    Mistake(
        "quat_conjugate_unchanged",
        "quat_conjugate",
        "returns q itself",
        """
def quat_conjugate(q):
    return np.array(q, dtype=float)
""",
        hint="returned q unchanged",
        public_hint="returned q unchanged",
    ),
    Mistake(
        "quat_conjugate_negates_all",
        "quat_conjugate",
        "returns -q",
        """
def quat_conjugate(q):
    return -np.asarray(q, dtype=float)
""",
        hint="returned -q",
        public_hint="returned -q",
    ),
    Mistake(
        "quat_conjugate_no_asarray",
        "quat_conjugate",
        "q * [1, -1, -1, -1] on a list fails",
        """
def quat_conjugate(q):
    return np.concatenate([q[:1], -q[1:]])
""",
        hint="np.asarray",
        public_hint="np.asarray",
    ),
    Mistake(
        "quat_inverse_divides_by_norm",
        "quat_inverse",
        "divides the conjugate by |q| instead of |q|²",
        """
def quat_inverse(q):
    q = np.asarray(q, dtype=float)
    return q * [1.0, -1.0, -1.0, -1.0] / np.linalg.norm(q)
""",
        hint="not by |q|²",
        public_hint="not by |q|²",
    ),
    Mistake(
        "quat_inverse_negates",
        "quat_inverse",
        "returns -q / |q|²",
        """
def quat_inverse(q):
    q = np.asarray(q, dtype=float)
    return -q / (q @ q)
""",
        hint="returned -q / |q|²",
        public_hint="returned -q / |q|²",
    ),
    Mistake(
        "quat_inverse_reciprocal",
        "quat_inverse",
        "1/q entry by entry",
        """
def quat_inverse(q):
    q = np.asarray(q, dtype=float)
    with np.errstate(divide="ignore"):
        return 1.0 / q
""",
        hint="entry by entry",
        public_hint="entry by entry",
    ),
    Mistake(
        "quat_from_axis_angle_unnormalised",
        "quat_from_axis_angle",
        "does not normalise the axis",
        """
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float)
    return np.concatenate([[np.cos(theta / 2)], np.sin(theta / 2) * u])
""",
        hint="divide u by its norm",
        public_hint="divide u by its norm",
    ),
    Mistake(
        "quat_from_axis_angle_sin_cos",
        "quat_from_axis_angle",
        "sin for the scalar, cos for the vector",
        """
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float) / np.linalg.norm(u)
    return np.concatenate([[np.sin(theta / 2)], np.cos(theta / 2) * u])
""",
        hint="sin and cos are swapped",
        public_hint="sin and cos are swapped",
    ),
    Mistake(
        "quat_rotate_no_conjugate",
        "quat_rotate",
        "q ⊗ v ⊗ q (no conjugate)",
        """
def quat_rotate(q, v):
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]], a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    q = np.asarray(q, dtype=float)
    return mul(mul(q, np.concatenate([[0.0], v])), q)[1:]
""",
        hint="conjugate is missing",
        public_hint="conjugate is missing",
    ),
    Mistake(
        "quat_rotate_scalar_last",
        "quat_rotate",
        "reads q as [x, y, z, w]",
        """
def quat_rotate(q, v):
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]], a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    q = np.roll(np.asarray(q, dtype=float), 1)
    return mul(mul(q, np.concatenate([[0.0], v])), q * [1, -1, -1, -1])[1:]
""",
        hint="scalar last",
        public_hint="scalar last",
    ),
    Mistake(
        "quat_rotate_half_formula",
        "quat_rotate",
        "v + 2w (u × v) only: drops the u × (u × v) term",
        """
def quat_rotate(q, v):
    q, v = np.asarray(q, dtype=float), np.asarray(v, dtype=float)
    return v + 2.0 * q[0] * np.cross(q[1:], v)
""",
        hint="second-order term",
        public_hint="second-order term",
    ),
    Mistake(
        "quat_to_matrix_no_factor_two",
        "quat_to_matrix",
        "forgets the factor 2",
        """
def quat_to_matrix(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[1 - (y * y + z * z), x * y - w * z, x * z + w * y],
                     [x * y + w * z, 1 - (x * x + z * z), y * z - w * x],
                     [x * z - w * y, y * z + w * x, 1 - (x * x + y * y)]])
""",
        hint="compare with your first column",
        public_hint="compare with your first column",
    ),
    Mistake(
        "quat_to_matrix_unnormalised",
        "quat_to_matrix",
        "uses the half angle as if q were the axis-angle",
        """
def quat_to_matrix(q):
    w, x, y, z = np.asarray(q, dtype=float)
    K = np.array([[0.0, -z, y], [z, 0.0, -x], [-y, x, 0.0]])
    return np.eye(3) + w * K + K @ K
""",
        hint="compare with your first column",
        public_hint="compare with your first column",
    ),
    Mistake(
        "matrix_to_quat_scalar_last",
        "matrix_to_quat",
        "returns [x, y, z, w]",
        """
def matrix_to_quat(R):
    R = np.asarray(R, dtype=float)
    t = np.trace(R)
    k = int(np.argmax([t, R[0, 0], R[1, 1], R[2, 2]]))
    q = [np.array([1 + t, R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]),
         np.array([R[2, 1] - R[1, 2], 1 + 2 * R[0, 0] - t, R[0, 1] + R[1, 0], R[0, 2] + R[2, 0]]),
         np.array([R[0, 2] - R[2, 0], R[0, 1] + R[1, 0], 1 + 2 * R[1, 1] - t, R[1, 2] + R[2, 1]]),
         np.array([R[1, 0] - R[0, 1], R[0, 2] + R[2, 0], R[1, 2] + R[2, 1], 1 + 2 * R[2, 2] - t])][k]
    q = q / np.linalg.norm(q) * (1.0 if q[0] >= 0 else -1.0)
    return np.roll(q, -1)
""",
        hint="scalar-last",
        public_hint="scalar-last",
    ),
    Mistake(
        "matrix_to_quat_transposed",
        "matrix_to_quat",
        "R - Rᵀ read the wrong way round (the conjugate)",
        """
def matrix_to_quat(R):
    R = np.asarray(R, dtype=float).T
    t = np.trace(R)
    k = int(np.argmax([t, R[0, 0], R[1, 1], R[2, 2]]))
    q = [np.array([1 + t, R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]]),
         np.array([R[2, 1] - R[1, 2], 1 + 2 * R[0, 0] - t, R[0, 1] + R[1, 0], R[0, 2] + R[2, 0]]),
         np.array([R[0, 2] - R[2, 0], R[0, 1] + R[1, 0], 1 + 2 * R[1, 1] - t, R[1, 2] + R[2, 1]]),
         np.array([R[1, 0] - R[0, 1], R[0, 2] + R[2, 0], R[1, 2] + R[2, 1], 1 + 2 * R[2, 2] - t])][k]
    return q / np.linalg.norm(q) * (1.0 if q[0] >= 0 else -1.0)
""",
        hint="conjugate",
        public_hint="conjugate",
    ),
    Mistake(
        "wxyz_to_xyzw_no_move",
        "wxyz_to_xyzw",
        "returns q unchanged",
        """
def wxyz_to_xyzw(q):
    return np.array(q, dtype=float)
""",
        hint="unchanged",
        public_hint="unchanged",
    ),
    Mistake(
        "wxyz_to_xyzw_wrong_roll",
        "wxyz_to_xyzw",
        "rolls the wrong way ([z, w, x, y])",
        """
def wxyz_to_xyzw(q):
    return np.roll(np.asarray(q, dtype=float), 1, axis=-1)
""",
        hint="wrong way",
        public_hint="wrong way",
    ),
    Mistake(
        "wxyz_to_xyzw_single_only",
        "wxyz_to_xyzw",
        "np.roll without axis: wrong for a stack",
        """
def wxyz_to_xyzw(q):
    q = np.asarray(q, dtype=float)
    return np.roll(q.ravel(), -1).reshape(q.shape)
""",
        hint="flat array",
        public_hint="flat array",
    ),
    Mistake(
        "xyzw_to_wxyz_reversed",
        "xyzw_to_wxyz",
        "reverses the array",
        """
def xyzw_to_wxyz(q):
    return np.asarray(q, dtype=float)[..., ::-1].copy()
""",
        hint="reversed",
        public_hint="reversed",
    ),
    Mistake(
        "xyzw_to_wxyz_no_move",
        "xyzw_to_wxyz",
        "returns q unchanged",
        """
def xyzw_to_wxyz(q):
    return np.array(q, dtype=float)
""",
        hint="unchanged",
        public_hint="unchanged",
    ),
    Mistake(
        "xyzw_to_wxyz_single_only",
        "xyzw_to_wxyz",
        "np.roll without axis: wrong for a stack",
        """
def xyzw_to_wxyz(q):
    q = np.asarray(q, dtype=float)
    return np.roll(q.ravel(), 1).reshape(q.shape)
""",
        hint="flat array",
        public_hint="flat array",
    ),
    Mistake(
        "quat_slerp_nlerp",
        "quat_slerp",
        "normalised linear interpolation (with the sign flip) instead of slerp",
        """
def quat_slerp(q0, q1, t):
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    if q0 @ q1 < 0:
        q1 = -q1
    q = (1 - t) * q0 + t * q1
    return q / np.linalg.norm(q)
""",
        hint="nlerp",
        public_hint="nlerp",
        classic=True,
    ),
    Mistake(
        "quat_slerp_no_small_branch",
        "quat_slerp",
        "divides by sin Ω even when the inputs are equal",
        """
def quat_slerp(q0, q1, t):
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    if q0 @ q1 < 0:
        q1 = -q1
    omega = np.arccos(np.clip(q0 @ q1, -1.0, 1.0))
    with np.errstate(invalid="ignore", divide="ignore"):
        return (np.sin((1 - t) * omega) * q0 + np.sin(t * omega) * q1) / np.sin(omega)
""",
        hint="when sin Ω is tiny",
        public_hint="when sin Ω is tiny",
    ),
    Mistake(
        "quat_multiply_normalised",
        "quat_multiply",
        "normalises the product (right for unit quaternions only)",
        """
def quat_multiply(p, q):
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    r = np.concatenate([[p[0] * q[0] - p[1:] @ q[1:]], p[0] * q[1:] + q[0] * p[1:] + np.cross(p[1:], q[1:])])
    return r / np.linalg.norm(r)
""",
        hint="divided by its norm",
        public_hint="divided by its norm",
    ),
    Mistake(
        "quat_right_one_sign",
        "quat_right",
        "one sign slipped in the second row (-z instead of z): not orthogonal any more",
        """
def quat_right(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z],
                     [x, w, -z, -y],
                     [y, -z, w, x],
                     [z, y, -x, w]])
""",
        hint="the four columns must be orthonormal",
        public_hint="one sign at a time",
    ),
    Mistake(
        "quat_slerp_weights_swapped",
        "quat_slerp",
        "the weights sin((1 - t)Ω) and sin(tΩ) swapped: t = 0 gives q1",
        """
def quat_slerp(q0, q1, t):
    q0 = np.asarray(q0, dtype=float)
    q1 = np.asarray(q1, dtype=float)
    d = q0 @ q1
    if d < 0.0:
        q1, d = -q1, -d
    omega = np.arccos(min(d, 1.0))
    if np.sin(omega) < 1e-12:
        q = (1.0 - t) * q0 + t * q1
    else:
        q = (np.sin(t * omega) * q0 + np.sin((1.0 - t) * omega) * q1) / np.sin(omega)
    return q / np.linalg.norm(q)
""",
        hint="the turn from q0 must grow as t × the whole angle",
        public_hint="the turn from q0 must grow as t × the whole angle",
    ),
]

ALTERNATIVES = [
    Alternative(
        "quat_multiply_matrix_list",
        "quat_multiply",
        "through the left-product matrix",
        """
def quat_multiply(p, q):
    w, x, y, z = np.asarray(p, dtype=float)
    L = np.array([[w, -x, -y, -z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])
    return L @ np.asarray(q, dtype=float)
""",
    ),
    Alternative(
        "quat_left_blocks",
        "quat_left",
        "from blocks w I + [[0, -vᵀ], [v, [v]×]]",
        """
def quat_left(q):
    q = np.asarray(q, dtype=float)
    w, v = q[0], q[1:]
    M = w * np.eye(4)
    M[0, 1:], M[1:, 0] = -v, v
    M[1:, 1:] += np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])
    return M
""",
    ),
    Alternative(
        "quat_right_columns",
        "quat_right",
        "columns are q ⊗ e_k",
        """
def quat_right(q):
    q = np.asarray(q, dtype=float)
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]], a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    return np.column_stack([mul(e, q) for e in np.eye(4)])
""",
    ),
    Alternative(
        "quat_inverse_solve",
        "quat_inverse",
        "solves [q]_L x = 1",
        """
def quat_inverse(q):
    w, x, y, z = np.asarray(q, dtype=float)
    L = np.array([[w, -x, -y, -z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])
    return np.linalg.solve(L, [1.0, 0.0, 0.0, 0.0])
""",
    ),
    Alternative(
        "quat_from_axis_angle_list",
        "quat_from_axis_angle",
        "built from a plain list of four numbers",
        """
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float) / np.linalg.norm(u)
    s = np.sin(theta / 2)
    return np.array([np.cos(theta / 2), s * u[0], s * u[1], s * u[2]])
""",
    ),
    Alternative(
        "quat_rotate_cross_form",
        "quat_rotate",
        "v + 2w (u × v) + 2 u × (u × v)",
        """
def quat_rotate(q, v):
    q, v = np.asarray(q, dtype=float), np.asarray(v, dtype=float)
    t = 2.0 * np.cross(q[1:], v)
    return v + q[0] * t + np.cross(q[1:], t)
""",
    ),
    Alternative(
        "quat_to_matrix_products",
        "quat_to_matrix",
        "[q]_L [q*]_R restricted to the vector block",
        """
def quat_to_matrix(q):
    w, x, y, z = np.asarray(q, dtype=float)
    L = np.array([[w, -x, -y, -z], [x, w, -z, y], [y, z, w, -x], [z, -y, x, w]])
    Rc = np.array([[w, x, y, z], [-x, w, -z, y], [-y, z, w, -x], [-z, -y, x, w]])
    return (L @ Rc)[1:, 1:]
""",
    ),
    Alternative(
        "matrix_to_quat_davenport",
        "matrix_to_quat",
        "Davenport's q-method: the top eigenvector of K",
        """
def matrix_to_quat(R):
    R = np.asarray(R, dtype=float)
    t = np.trace(R)
    K = np.array([[t, R[2, 1] - R[1, 2], R[0, 2] - R[2, 0], R[1, 0] - R[0, 1]],
                  [R[2, 1] - R[1, 2], 2 * R[0, 0] - t, R[0, 1] + R[1, 0], R[0, 2] + R[2, 0]],
                  [R[0, 2] - R[2, 0], R[0, 1] + R[1, 0], 2 * R[1, 1] - t, R[1, 2] + R[2, 1]],
                  [R[1, 0] - R[0, 1], R[0, 2] + R[2, 0], R[1, 2] + R[2, 1], 2 * R[2, 2] - t]]) / 3.0
    values, vectors = np.linalg.eigh(K)
    q = vectors[:, -1]
    return -q if q[0] < 0 else q
""",
    ),
    Alternative(
        "wxyz_to_xyzw_roll",
        "wxyz_to_xyzw",
        "np.roll along the last axis",
        """
def wxyz_to_xyzw(q):
    return np.roll(np.asarray(q, dtype=float), -1, axis=-1)
""",
    ),
    Alternative(
        "xyzw_to_wxyz_index",
        "xyzw_to_wxyz",
        "fancy indexing [3, 0, 1, 2]",
        """
def xyzw_to_wxyz(q):
    return np.asarray(q, dtype=float)[..., [3, 0, 1, 2]]
""",
    ),
    Alternative(
        "quat_slerp_power",
        "quat_slerp",
        "power form q0 ⊗ (q0* ⊗ q1)^t through the log",
        """
def quat_slerp(q0, q1, t):
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]], a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    d = mul(q0 * [1, -1, -1, -1], q1)
    if d[0] < 0:
        d = -d
    n = np.linalg.norm(d[1:])
    half = np.arctan2(n, d[0])
    axis = d[1:] / n if n > 0 else np.zeros(3)
    return mul(q0, np.concatenate([[np.cos(t * half)], np.sin(t * half) * axis]))
""",
    ),
    Alternative(
        "quat_slerp_nlerp_below_1e_6",
        "quat_slerp",
        "falls back to a normalised blend below Ω = 1e-6, takes lists",
        """
def quat_slerp(q0, q1, t):
    q0, q1 = np.asarray(q0, dtype=float), np.asarray(q1, dtype=float)
    if q0 @ q1 < 0:
        q1 = -q1
    omega = np.arccos(np.clip(q0 @ q1, -1.0, 1.0))
    if omega < 1e-6:
        q = (1 - t) * q0 + t * q1
    else:
        q = np.sin((1 - t) * omega) * q0 + np.sin(t * omega) * q1
    return q / np.linalg.norm(q)
""",
    ),
]

SAMPLE = {
    "chloe": ["quat_multiply_cross_flipped"],
    "dev": ["quat_to_matrix_transposed", "quat_rotate_conjugate_left"],
    "emma": ["quat_from_axis_angle_degrees"],
    "farid": ["matrix_to_quat_no_canonical", "quat_slerp_long_arc"],
}
