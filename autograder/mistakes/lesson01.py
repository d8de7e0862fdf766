"""Typical mistakes for lesson 01: frames, points and rotation matrices."""

from . import Mistake

MISTAKES = [
    Mistake("rot_z_transposed", "rot_z", "minus sign on the wrong sine (the transpose)", '''
def rot_z(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, s, 0.0], [-s, c, 0.0], [0.0, 0.0, 1.0]])
'''),
    Mistake("rot_y_sign_top_right", "rot_y", "rot_y written like rot_x and rot_z, minus sign top-right", '''
def rot_y(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0.0, -s], [0.0, 1.0, 0.0], [s, 0.0, c]])
'''),
    Mistake("rot_x_degrees", "rot_x", "treats the angle as degrees", '''
def rot_x(a):
    c, s = np.cos(np.deg2rad(a)), np.sin(np.deg2rad(a))
    return np.array([[1.0, 0.0, 0.0], [0.0, c, -s], [0.0, s, c]])
'''),
    Mistake("rot_y_degrees", "rot_y", "treats the angle as degrees", '''
def rot_y(a):
    a = np.radians(a)
    return np.array([[np.cos(a), 0.0, np.sin(a)], [0.0, 1.0, 0.0], [-np.sin(a), 0.0, np.cos(a)]])
'''),
    Mistake("rot_z_degrees", "rot_z", "treats the angle as degrees", '''
def rot_z(a):
    a = a * np.pi / 180
    return np.array([[np.cos(a), -np.sin(a), 0.0], [np.sin(a), np.cos(a), 0.0], [0.0, 0.0, 1.0]])
'''),
    Mistake("rot2d_clockwise", "rot2d", "clockwise instead of counter-clockwise", '''
def rot2d(theta):
    return np.array([[np.cos(theta), np.sin(theta)], [-np.sin(theta), np.cos(theta)]])
'''),
    Mistake("is_rotation_no_det", "is_rotation_matrix", "checks orthogonality only, so accepts reflections", '''
def is_rotation_matrix(M, tol=1e-9):
    M = np.asarray(M, dtype=float)
    if M.ndim != 2 or M.shape[0] != M.shape[1]:
        return False
    return bool(np.allclose(M.T @ M, np.eye(M.shape[0]), atol=tol))
'''),
    Mistake("is_rotation_crashes_on_shape", "is_rotation_matrix", "no shape check: crashes on a 3×4 matrix", '''
def is_rotation_matrix(M, tol=1e-9):
    M = np.asarray(M, dtype=float)
    return bool(np.max(np.abs(M.T @ M - np.eye(3))) <= tol and np.linalg.det(M) > 0)
'''),
    Mistake("rotate_point_transposed", "rotate_point", "uses R_wb.T (the inverse rotation)", '''
def rotate_point(R_wb, p_b):
    return np.asarray(p_b, dtype=float) @ np.asarray(R_wb, dtype=float)
'''),
    Mistake("rotate_point_single_only", "rotate_point", "R @ p: right for one point, wrong for rows", '''
def rotate_point(R_wb, p_b):
    R_wb = np.asarray(R_wb, dtype=float)
    p_b = np.asarray(p_b, dtype=float)
    return R_wb @ p_b
'''),
    Mistake("compose_reversed", "compose", "multiplies in the wrong order", '''
def compose(R_ab, R_bc):
    return np.asarray(R_bc, dtype=float) @ np.asarray(R_ab, dtype=float)
'''),
    Mistake("invert_rotation_identity", "invert_rotation", "returns the rotation itself", '''
def invert_rotation(R_ab):
    return np.array(R_ab, dtype=float)
'''),
    Mistake("nearest_rotation_reflection", "nearest_rotation", "U Vᵀ without the determinant fix", '''
def nearest_rotation(M):
    U, _, Vt = np.linalg.svd(np.asarray(M, dtype=float))
    return U @ Vt
'''),
    Mistake("rot2d_endless_loop", "rot2d", "an endless loop", '''
def rot2d(theta):
    while theta == theta:
        theta = theta + 0.0
    return np.eye(2)
''', kind="fault"),
    Mistake("compose_exits", "compose", "calls os._exit when called", '''
import os

def compose(R_ab, R_bc):
    os._exit(1)
''', kind="fault"),
    Mistake("invert_rotation_recursion", "invert_rotation", "unbounded recursion", '''
def invert_rotation(R_ab):
    return invert_rotation(R_ab).T
''', kind="fault"),
]

SAMPLE = {
    "dev": ["rot_z_transposed", "rotate_point_transposed"],
    "emma": ["rot_x_degrees", "rot_y_degrees", "rot_z_degrees"],
    "farid": ["is_rotation_no_det", "nearest_rotation_reflection"],
    "ivy": ["rot2d_endless_loop", "compose_exits", "invert_rotation_recursion"],
}
