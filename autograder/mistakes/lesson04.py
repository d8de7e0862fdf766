"""Typical mistakes for lesson 04: quaternions."""

from . import Mistake

MISTAKES = [
    Mistake("quat_multiply_cross_flipped", "quat_multiply",
            "cross product with the wrong sign (the JPL product, ij = -k)", '''
def quat_multiply(p, q):
    p = np.asarray(p, dtype=float)
    q = np.asarray(q, dtype=float)
    w = p[0] * q[0] - p[1:] @ q[1:]
    v = p[0] * q[1:] + q[0] * p[1:] - np.cross(p[1:], q[1:])
    return np.concatenate([[w], v])
'''),
    Mistake("quat_left_transposed", "quat_left", "typed [q]_L with rows and columns swapped", '''
def quat_left(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, x, y, z],
                     [-x, w, z, -y],
                     [-y, -z, w, x],
                     [-z, y, -x, w]])
'''),
    Mistake("quat_right_wrong_cross_sign", "quat_right", "[q]_R with +[v]× (a copy of [q]_L)", '''
def quat_right(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[w, -x, -y, -z],
                     [x, w, -z, y],
                     [y, z, w, -x],
                     [z, -y, x, w]])
'''),
    Mistake("quat_conjugate_negates_scalar", "quat_conjugate", "negates the scalar part instead of the vector", '''
def quat_conjugate(q):
    q = np.array(q, dtype=float)
    q[0] = -q[0]
    return q
'''),
    Mistake("quat_inverse_no_norm", "quat_inverse", "returns the conjugate without dividing by |q|²", '''
def quat_inverse(q):
    q = np.asarray(q, dtype=float)
    return np.array([q[0], -q[1], -q[2], -q[3]])
'''),
    Mistake("quat_from_axis_angle_full_angle", "quat_from_axis_angle", "uses θ instead of θ/2", '''
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    return np.concatenate([[np.cos(theta)], np.sin(theta) * u])
'''),
    Mistake("quat_from_axis_angle_degrees", "quat_from_axis_angle", "treats the angle as degrees", '''
def quat_from_axis_angle(u, theta):
    u = np.asarray(u, dtype=float)
    u = u / np.linalg.norm(u)
    half = np.radians(theta) / 2
    return np.concatenate([[np.cos(half)], np.sin(half) * u])
'''),
    Mistake("quat_rotate_conjugate_left", "quat_rotate", "q* ⊗ v ⊗ q: rotates the opposite way", '''
def quat_rotate(q, v):
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]],
                               a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    q = np.asarray(q, dtype=float)
    q_conj = np.concatenate([q[:1], -q[1:]])
    return mul(mul(q_conj, np.concatenate([[0.0], v])), q)[1:]
'''),
    Mistake("quat_to_matrix_transposed", "quat_to_matrix", "the 2w[v]× terms with the wrong sign (the transpose)", '''
def quat_to_matrix(q):
    w, x, y, z = np.asarray(q, dtype=float)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y + w * z), 2 * (x * z - w * y)],
                     [2 * (x * y - w * z), 1 - 2 * (x * x + z * z), 2 * (y * z + w * x)],
                     [2 * (x * z + w * y), 2 * (y * z - w * x), 1 - 2 * (x * x + y * y)]])
'''),
    Mistake("quat_to_matrix_scalar_last", "quat_to_matrix", "reads q as scalar last [x, y, z, w]", '''
def quat_to_matrix(q):
    x, y, z, w = np.asarray(q, dtype=float)
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
'''),
    Mistake("matrix_to_quat_naive", "matrix_to_quat", "w = √(1 + tr R)/2, then divide by 4w: fails near π", '''
def matrix_to_quat(R):
    R = np.asarray(R, dtype=float)
    w = 0.5 * np.sqrt(1.0 + np.trace(R))
    x = (R[2, 1] - R[1, 2]) / (4 * w)
    y = (R[0, 2] - R[2, 0]) / (4 * w)
    z = (R[1, 0] - R[0, 1]) / (4 * w)
    return np.array([w, x, y, z])
'''),
    Mistake("matrix_to_quat_no_canonical", "matrix_to_quat", "Shepperd's branches but w < 0 is not flipped", '''
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
'''),
    Mistake("wxyz_to_xyzw_reversed", "wxyz_to_xyzw", "reverses the array ([z, y, x, w])", '''
def wxyz_to_xyzw(q):
    return np.asarray(q, dtype=float)[..., ::-1]
'''),
    Mistake("xyzw_to_wxyz_wrong_roll", "xyzw_to_wxyz", "rolls the wrong way ([y, z, w, x])", '''
def xyzw_to_wxyz(q):
    return np.roll(np.asarray(q, dtype=float), -1, axis=-1)
'''),
    Mistake("quat_slerp_long_arc", "quat_slerp", "no sign flip when q0 · q1 < 0: the longer arc", '''
def quat_slerp(q0, q1, t):
    q0 = np.asarray(q0, dtype=float)
    q1 = np.asarray(q1, dtype=float)
    omega = np.arccos(np.clip(q0 @ q1, -1.0, 1.0))
    if np.sin(omega) < 1e-12:
        return q0.copy()
    return (np.sin((1 - t) * omega) * q0 + np.sin(t * omega) * q1) / np.sin(omega)
'''),
    Mistake("quat_slerp_linear", "quat_slerp", "plain linear interpolation, not normalised", '''
def quat_slerp(q0, q1, t):
    q0 = np.asarray(q0, dtype=float)
    q1 = np.asarray(q1, dtype=float)
    if q0 @ q1 < 0:
        q1 = -q1
    return (1 - t) * q0 + t * q1
'''),
]

SAMPLE = {
    "chloe": ["quat_multiply_cross_flipped"],
    "dev": ["quat_to_matrix_transposed", "quat_rotate_conjugate_left"],
    "emma": ["quat_from_axis_angle_degrees"],
    "farid": ["matrix_to_quat_no_canonical", "quat_slerp_long_arc"],
}
