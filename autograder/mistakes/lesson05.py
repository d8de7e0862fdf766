"""Typical mistakes for lesson 05: Euler angles and their singularities."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "euler_matrix_xyz_order",
        "euler_zyx_to_matrix",
        "multiplies in the x-y-z order, Rx(roll) Ry(pitch) Rz(yaw)",
        """
def euler_zyx_to_matrix(yaw, pitch, roll):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    Rz = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
    Ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    Rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    return Rx @ Ry @ Rz
""",
        hint="x-y-z order",
        public_hint="x-y-z order",
    ),
    Mistake(
        "euler_matrix_degrees",
        "euler_zyx_to_matrix",
        "treats the angles as degrees",
        """
def euler_zyx_to_matrix(yaw, pitch, roll):
    yaw, pitch, roll = np.deg2rad([yaw, pitch, roll])
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    Rz = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
    Ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    Rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    return Rz @ Ry @ Rx
""",
        hint="looks like degrees",
        public_hint="looks like degrees",
    ),
    Mistake(
        "matrix_to_euler_asin_unclamped",
        "matrix_to_euler_zyx",
        "pitch = arcsin(-R[2, 0]) without clamping: NaN when rounding puts |R[2, 0]| above 1",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)
    pitch = np.arcsin(-R[2, 0])
    if np.cos(pitch) < 1e-12:
        return np.arctan2(-R[0, 1], R[1, 1]), pitch, 0.0
    return np.arctan2(R[1, 0], R[0, 0]), pitch, np.arctan2(R[2, 1], R[2, 2])
""",
        hint="hair beyond ±1",
        public_hint="hair beyond ±1",
    ),
    Mistake(
        "matrix_to_euler_roll_not_zeroed",
        "matrix_to_euler_zyx",
        "no gimbal-lock branch: yaw and roll from the tiny entries, roll not zeroed at the lock",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)
    pitch = np.arctan2(-R[2, 0], np.hypot(R[0, 0], R[1, 0]))
    yaw = np.arctan2(R[1, 0], R[0, 0])
    roll = np.arctan2(R[2, 1], R[2, 2])
    return yaw, pitch, roll
""",
        hint="no separate gimbal-lock branch",
        public_hint="no separate gimbal-lock branch",
    ),
    Mistake(
        "matrix_to_euler_roll_first",
        "matrix_to_euler_zyx",
        "returns (roll, pitch, yaw): yaw and roll swapped in the return",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)
    cos_pitch = np.hypot(R[0, 0], R[1, 0])
    pitch = np.arctan2(-R[2, 0], cos_pitch)
    if cos_pitch < 1e-12:
        return 0.0, pitch, np.arctan2(-R[0, 1], R[1, 1])
    yaw = np.arctan2(R[1, 0], R[0, 0])
    c, s = np.cos(yaw), np.sin(yaw)
    roll = np.arctan2(s * R[0, 2] - c * R[1, 2], c * R[1, 1] - s * R[0, 1])
    return roll, pitch, yaw
""",
        hint="returned (roll, pitch, yaw)",
        public_hint="come back as (roll, pitch, yaw)",
    ),
    Mistake(
        "matrix_to_euler_scipy_extrinsic",
        "matrix_to_euler_zyx",
        "scipy's lowercase 'zyx' (extrinsic) instead of 'ZYX' (intrinsic)",
        """
def matrix_to_euler_zyx(R):
    from scipy.spatial.transform import Rotation
    yaw, pitch, roll = Rotation.from_matrix(np.asarray(R, dtype=float)).as_euler("zyx")
    return yaw, pitch, roll
""",
        hint="write the exercise with numpy yourself",
        public_hint="write the exercise with numpy yourself",
    ),
    Mistake(
        "euler_to_quat_full_angles",
        "euler_zyx_to_quat",
        "uses full angles instead of half angles",
        """
def euler_zyx_to_quat(yaw, pitch, roll):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    return np.array([cy * cp * cr + sy * sp * sr,
                     cy * cp * sr - sy * sp * cr,
                     cy * sp * cr + sy * cp * sr,
                     sy * cp * cr - cy * sp * sr])
""",
        hint="full angles",
        public_hint="full angles",
    ),
    Mistake(
        "euler_to_quat_extrinsic",
        "euler_zyx_to_quat",
        "multiplies q_x ⊗ q_y ⊗ q_z (the extrinsic reading of z-y-x)",
        """
def euler_zyx_to_quat(yaw, pitch, roll):
    def multiply(p, q):
        pw, px, py, pz = p
        qw, qx, qy, qz = q
        return np.array([pw * qw - px * qx - py * qy - pz * qz,
                         pw * qx + px * qw + py * qz - pz * qy,
                         pw * qy - px * qz + py * qw + pz * qx,
                         pw * qz + px * qy - py * qx + pz * qw])
    qz = [np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)]
    qy = [np.cos(pitch / 2), 0.0, np.sin(pitch / 2), 0.0]
    qx = [np.cos(roll / 2), np.sin(roll / 2), 0.0, 0.0]
    return multiply(multiply(qx, qy), qz)
""",
        hint="q_x ⊗ q_y ⊗ q_z",
        public_hint="q_x ⊗ q_y ⊗ q_z",
    ),
    Mistake(
        "quat_to_euler_lecture_verbatim",
        "quat_to_euler_zyx",
        "copies the formula under the lecture's swapped label as printed: [φ, θ, ψ] (roll first), unclamped asin",
        """
def quat_to_euler_zyx(q):
    w, x, y, z = np.asarray(q, dtype=float)
    phi = np.arctan2(2 * (w * x + y * z), 1 - 2 * (x ** 2 + y ** 2))
    theta = np.arcsin(2 * (w * y - z * x))
    psi = np.arctan2(2 * (w * z + x * y), 1 - 2 * (y ** 2 + z ** 2))
    return np.array([phi, theta, psi])
""",
        hint="returned (roll, pitch, yaw)",
        public_hint="come back as (roll, pitch, yaw)",
    ),
    Mistake(
        "quat_to_euler_clamped_asin",
        "quat_to_euler_zyx",
        "the lecture's formula in the right order with a clamped asin: no lock handling, inaccurate next to the lock",
        """
def quat_to_euler_zyx(q):
    w, x, y, z = np.asarray(q, dtype=float)
    roll = np.arctan2(2 * (w * x + y * z), 1 - 2 * (x ** 2 + y ** 2))
    pitch = np.arcsin(np.clip(2 * (w * y - z * x), -1.0, 1.0))
    yaw = np.arctan2(2 * (w * z + x * y), 1 - 2 * (y ** 2 + z ** 2))
    return yaw, pitch, roll
""",
        hint="no gimbal-lock branch",
        public_hint="no gimbal-lock branch",
    ),
    Mistake(
        "quat_to_euler_scalar_last",
        "quat_to_euler_zyx",
        "reads q as scalar-last [x, y, z, w]",
        """
def quat_to_euler_zyx(q):
    x, y, z, w = np.asarray(q, dtype=float) / np.linalg.norm(q)
    a, b = np.hypot(w + y, z - x), np.hypot(w - y, x + z)
    pitch = 2 * np.arctan2(a, b) - np.pi / 2
    wrap = lambda angle: float(np.pi - np.mod(np.pi - angle, 2 * np.pi))
    if b < 1e-12:
        return wrap(2 * np.arctan2(z - x, w + y)), pitch, 0.0
    if a < 1e-12:
        return wrap(2 * np.arctan2(x + z, w - y)), pitch, 0.0
    difference, total = 2 * np.arctan2(z - x, w + y), 2 * np.arctan2(x + z, w - y)
    return wrap((total + difference) / 2), pitch, wrap((total - difference) / 2)
""",
        hint="scalar-last",
        public_hint="scalar-last",
    ),
    Mistake(
        "euler_rates_rx_not_transposed",
        "euler_rates_matrix",
        "expresses the axes with Rx(roll) instead of Rx(roll)ᵀ (active/passive mix-up)",
        """
def euler_rates_matrix(pitch, roll):
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    return np.array([[-sp, 0.0, 1.0], [-cp * sr, cr, 0.0], [cp * cr, sr, 0.0]])
""",
        hint="roll signs are flipped",
        public_hint="roll signs are flipped",
    ),
    Mistake(
        "euler_rates_columns_reversed",
        "euler_rates_matrix",
        "columns ordered [roll_rate, pitch_rate, yaw_rate]",
        """
def euler_rates_matrix(pitch, roll):
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    return np.array([[1.0, 0.0, -sp], [0.0, cr, cp * sr], [0.0, -sr, cp * cr]])
""",
        hint="order [roll, pitch, yaw]",
        public_hint="order [roll, pitch, yaw]",
    ),
    Mistake(
        "euler_matrix_transposed",
        "euler_zyx_to_matrix",
        "returns Rᵀ (the inverse attitude)",
        """
def euler_zyx_to_matrix(yaw, pitch, roll):
    cy, sy, cp, sp, cr, sr = np.cos(yaw), np.sin(yaw), np.cos(pitch), np.sin(pitch), np.cos(roll), np.sin(roll)
    return np.array([[cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr],
                     [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
                     [-sp, cp * sr, cp * cr]]).T
""",
        hint="looks like the transpose",
        public_hint="looks like the transpose",
    ),
    Mistake(
        "euler_matrix_pitch_sign",
        "euler_zyx_to_matrix",
        "Ry written with the minus sign top-right",
        """
def euler_zyx_to_matrix(yaw, pitch, roll):
    cy, sy, cp, sp, cr, sr = np.cos(yaw), np.sin(yaw), np.cos(pitch), np.sin(pitch), np.cos(roll), np.sin(roll)
    Rz = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]])
    Ry = np.array([[cp, 0.0, -sp], [0.0, 1.0, 0.0], [sp, 0.0, cp]])
    Rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    return Rz @ Ry @ Rx
""",
        hint="pitch turns the wrong way",
        public_hint="pitch turns the wrong way",
    ),
    Mistake(
        "euler_to_quat_wrong_sign",
        "euler_zyx_to_quat",
        "all plus signs in the mixed products",
        """
def euler_zyx_to_quat(yaw, pitch, roll):
    cy, sy = np.cos(yaw / 2), np.sin(yaw / 2)
    cp, sp = np.cos(pitch / 2), np.sin(pitch / 2)
    cr, sr = np.cos(roll / 2), np.sin(roll / 2)
    return np.array([cy * cp * cr + sy * sp * sr, cy * cp * sr + sy * sp * cr,
                     cy * sp * cr + sy * cp * sr, sy * cp * cr + cy * sp * sr])
""",
        hint="lost their minus signs",
        public_hint="lost their minus signs",
    ),
    Mistake(
        "euler_to_quat_scalar_last",
        "euler_zyx_to_quat",
        "returns [x, y, z, w]",
        """
def euler_zyx_to_quat(yaw, pitch, roll):
    cy, sy = np.cos(yaw / 2), np.sin(yaw / 2)
    cp, sp = np.cos(pitch / 2), np.sin(pitch / 2)
    cr, sr = np.cos(roll / 2), np.sin(roll / 2)
    return np.array([cy * cp * sr - sy * sp * cr, cy * sp * cr + sy * cp * sr,
                     sy * cp * cr - cy * sp * sr, cy * cp * cr + sy * sp * sr])
""",
        hint="scalar-last",
        public_hint="scalar-last",
    ),
    Mistake(
        "quat_to_euler_swapped_yaw_roll",
        "quat_to_euler_zyx",
        "returns (roll, pitch, yaw)",
        """
def quat_to_euler_zyx(q):
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    roll = np.arctan2(2 * (w * x + y * z), 1 - 2 * (x * x + y * y))
    pitch = np.arcsin(np.clip(2 * (w * y - z * x), -1.0, 1.0))
    yaw = np.arctan2(2 * (w * z + x * y), 1 - 2 * (y * y + z * z))
    return float(roll), float(pitch), float(yaw)
""",
        hint="returned (roll, pitch, yaw)",
        public_hint="come back as (roll, pitch, yaw)",
    ),
    Mistake(
        "euler_rates_transposed",
        "euler_rates_matrix",
        "returns Eᵀ",
        """
def euler_rates_matrix(pitch, roll):
    cp, sp, cr, sr = np.cos(pitch), np.sin(pitch), np.cos(roll), np.sin(roll)
    return np.array([[-sp, 0.0, 1.0], [sr * cp, cr, 0.0], [cr * cp, -sr, 0.0]]).T
""",
        hint="transpose of E",
        public_hint="transpose of E",
    ),
    Mistake(
        "euler_rates_identity",
        "euler_rates_matrix",
        "body rates = Euler-angle rates (E = I)",
        """
def euler_rates_matrix(pitch, roll):
    return np.eye(3)
""",
        hint="Euler-angle rates as body rates",
        public_hint="Euler-angle rates as body rates",
    ),
    Mistake(
        "matrix_to_euler_lock_test_too_strict",
        "matrix_to_euler_zyx",
        "has a gimbal-lock branch, but tests cos(pitch) == 0, which rounding seldom gives",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)

    def half_open(angle):
        # atan2 may return -π; the course's range is (-π, π].
        return float(angle + 2 * np.pi) if angle <= -np.pi else float(angle)

    # cos(pitch) is the length of (R00, R10) and also of (R21, R22): average both.
    cos_pitch = np.sqrt(0.5 * (R[0, 0] ** 2 + R[1, 0] ** 2 + R[2, 1] ** 2 + R[2, 2] ** 2))
    pitch = np.arctan2(-R[2, 0], cos_pitch)          # never nan, accurate next to ±π/2
    if cos_pitch == 0.0:
        # Gimbal lock: roll = 0, and R = Rz(yaw) Ry(±π/2) has middle column (-sin yaw, cos yaw, 0).
        return half_open(np.arctan2(-R[0, 1], R[1, 1])), float(pitch), 0.0
    yaw = np.arctan2(R[1, 0], R[0, 0])
    # Undo the yaw: Rz(yaw)ᵀ R = Ry(pitch) Rx(roll), whose middle row is (0, cos roll, -sin roll).
    c, s = np.cos(yaw), np.sin(yaw)
    roll = np.arctan2(s * R[0, 2] - c * R[1, 2], c * R[1, 1] - s * R[0, 1])
    return half_open(yaw), float(pitch), half_open(roll)
""",
        hint="no separate gimbal-lock branch, or a lock test too strict",
        public_hint="no separate gimbal-lock branch, or a lock test too strict",
    ),
    Mistake(
        "euler_matrix_one_sign",
        "euler_zyx_to_matrix",
        "one sign slipped in the first row (+ sy cr instead of - sy cr): not a rotation",
        """
def euler_zyx_to_matrix(yaw, pitch, roll):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cr, sr = np.cos(roll), np.sin(roll)
    return np.array([
        [cy * cp, cy * sp * sr + sy * cr, cy * sp * cr + sy * sr],
        [sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr],
        [-sp, cp * sr, cp * cr],
    ])
""",
        hint="compare each elementary rotation with a quarter turn",
        public_hint="columns are not orthonormal",
    ),
    Mistake(
        "euler_angles_as_list",
        "matrix_to_euler_zyx",
        "returns [yaw, pitch, roll] as a list where the docstring promises a tuple of three floats",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)
    fold = lambda a: float(a + 2 * np.pi) if a <= -np.pi else float(a)
    cos_pitch = np.hypot(R[0, 0], R[1, 0])
    pitch = float(np.arctan2(-R[2, 0], cos_pitch))
    if cos_pitch < 1e-12:
        return [fold(np.arctan2(-R[0, 1], R[1, 1])), pitch, 0.0]
    return [fold(np.arctan2(R[1, 0], R[0, 0])), pitch, fold(np.arctan2(R[2, 1], R[2, 2]))]
""",
        hint="a list is not an array",
        public_hint="a list is not an array",
    ),
]

ALTERNATIVES = [
    Alternative(
        "matrix_to_euler_undo_yaw",
        "matrix_to_euler_zyx",
        "pitch and roll from Rz(yaw)ᵀ R",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)
    fold = lambda a: float(np.pi if a <= -np.pi else a)
    if np.hypot(R[0, 0], R[1, 0]) < 1e-12 and np.hypot(R[2, 1], R[2, 2]) < 1e-12:
        return fold(np.arctan2(-R[0, 1], R[1, 1])), float(np.arctan2(-R[2, 0], 0.0)), 0.0
    yaw = np.arctan2(R[1, 0], R[0, 0])
    c, s = np.cos(yaw), np.sin(yaw)
    A = np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]]) @ R          # Ry(pitch) Rx(roll)
    return fold(yaw), float(np.arctan2(-A[2, 0], A[0, 0])), fold(np.arctan2(-A[1, 2], A[1, 1]))
""",
    ),
    Alternative(
        "euler_matrix_product_list",
        "euler_zyx_to_matrix",
        "Rz @ Ry @ Rx, each built by index",
        """
def euler_zyx_to_matrix(yaw, pitch, roll):
    def rot(axis, a):
        c, s = np.cos(a), np.sin(a)
        i, j = [k for k in range(3) if k != axis]
        M = np.eye(3)
        M[i, i], M[i, j], M[j, i], M[j, j] = c, -s, s, c
        return M.T if axis == 1 else M
    return rot(2, yaw) @ rot(1, pitch) @ rot(0, roll)
""",
    ),
    Alternative(
        "euler_to_quat_products",
        "euler_zyx_to_quat",
        "q_z ⊗ q_y ⊗ q_x",
        """
def euler_zyx_to_quat(yaw, pitch, roll):
    def mul(a, b):
        return np.concatenate([[a[0] * b[0] - a[1:] @ b[1:]], a[0] * b[1:] + b[0] * a[1:] + np.cross(a[1:], b[1:])])
    qz = np.array([np.cos(yaw / 2), 0.0, 0.0, np.sin(yaw / 2)])
    qy = np.array([np.cos(pitch / 2), 0.0, np.sin(pitch / 2), 0.0])
    qx = np.array([np.cos(roll / 2), np.sin(roll / 2), 0.0, 0.0])
    return mul(mul(qz, qy), qx)
""",
    ),
    Alternative(
        "quat_to_euler_via_matrix",
        "quat_to_euler_zyx",
        "builds R from q, then atan2/hypot extraction with a lock branch and roll from Rz(yaw)ᵀ R",
        """
def quat_to_euler_zyx(q):
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    R = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                  [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                  [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
    fold = lambda a: float(np.pi if a <= -np.pi else a)
    cos_pitch = np.hypot(R[0, 0], R[1, 0])
    pitch = float(np.arctan2(-R[2, 0], cos_pitch))
    if cos_pitch < 1e-12 and np.hypot(R[2, 1], R[2, 2]) < 1e-12:
        return fold(np.arctan2(-R[0, 1], R[1, 1])), pitch, 0.0
    yaw = np.arctan2(R[1, 0], R[0, 0])
    c, s = np.cos(yaw), np.sin(yaw)
    roll = np.arctan2(s * R[0, 2] - c * R[1, 2], c * R[1, 1] - s * R[0, 1])
    return fold(yaw), pitch, fold(roll)
""",
    ),
    Alternative(
        "quat_to_euler_complex_angles",
        "quat_to_euler_zyx",
        "yaw ∓ roll as arguments of the complex numbers (w + y) + i(z - x) and (w - y) + i(x + z)",
        """
def quat_to_euler_zyx(q):
    w, x, y, z = np.asarray(q, dtype=float) / np.linalg.norm(q)
    u, v = complex(w + y, z - x), complex(w - y, x + z)     # |u| = √2 sin(pitch/2 + π/4), |v| = √2 cos(...)
    pitch = 2 * np.arctan2(abs(u), abs(v)) - np.pi / 2
    wrap = lambda a: float(np.pi - (np.pi - a) % (2 * np.pi))     # into (-π, π]: -π becomes π
    if abs(v) < 1e-12:
        return wrap(2 * np.angle(u)), float(pitch), 0.0
    if abs(u) < 1e-12:
        return wrap(2 * np.angle(v)), float(pitch), 0.0
    difference, total = 2 * np.angle(u), 2 * np.angle(v)
    return wrap((total + difference) / 2), float(pitch), wrap((total - difference) / 2)
""",
    ),
    Alternative(
        "euler_rates_columns",
        "euler_rates_matrix",
        "columns are the axes e_z, e_y, e_x seen in the body",
        """
def euler_rates_matrix(pitch, roll):
    cp, sp, cr, sr = np.cos(pitch), np.sin(pitch), np.cos(roll), np.sin(roll)
    Rx = np.array([[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]])
    Ry = np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]])
    return np.column_stack([Rx.T @ Ry.T @ [0.0, 0.0, 1.0], Rx.T @ [0.0, 1.0, 0.0], [1.0, 0.0, 0.0]])
""",
    ),
    Alternative(
        "matrix_to_euler_wrapped_by_mod",
        "matrix_to_euler_zyx",
        "wraps yaw and roll into (-π, π] with np.mod",
        """
def matrix_to_euler_zyx(R):
    R = np.asarray(R, dtype=float)
    wrap = lambda a: float(np.pi - np.mod(np.pi - a, 2 * np.pi))
    pitch = float(np.arctan2(-R[2, 0], np.hypot(R[0, 0], R[1, 0])))
    if np.hypot(R[0, 0], R[1, 0]) < 1e-12:
        return wrap(np.arctan2(-R[0, 1], R[1, 1])), pitch, 0.0
    yaw = np.arctan2(R[1, 0], R[0, 0])
    c, s = np.cos(yaw), np.sin(yaw)
    return wrap(yaw), pitch, wrap(np.arctan2(s * R[0, 2] - c * R[1, 2], c * R[1, 1] - s * R[0, 1]))
""",
    ),
]

SAMPLE = {
    "dev": ["euler_rates_rx_not_transposed"],
    "emma": ["euler_matrix_degrees"],
    "farid": ["matrix_to_euler_roll_not_zeroed"],
    "chloe": ["matrix_to_euler_asin_unclamped"],
}
