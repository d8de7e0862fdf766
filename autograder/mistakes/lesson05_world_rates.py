"""Typical mistakes for lesson 05, section 9: Euler-angle rates in world axes."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "world_rates_transposed_turns",
        "euler_rates_matrix_world",
        "turns the axes by transposes, as for the body rates",
        """
def euler_rates_matrix_world(yaw, pitch):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    Rz_T = np.array([[cy, sy, 0.0], [-sy, cy, 0.0], [0.0, 0.0, 1.0]])
    Ry_T = np.array([[cp, 0.0, -sp], [0.0, 1.0, 0.0], [sp, 0.0, cp]])
    return np.column_stack([[0.0, 0.0, 1.0], Rz_T @ [0.0, 1.0, 0.0], Ry_T @ Rz_T @ [1.0, 0.0, 0.0]])
""",
        hint="gives at the opposite yaw",
        public_hint="gives at the opposite yaw",
        classic=True,
    ),
    Mistake(
        "world_rates_roll_unpitched",
        "euler_rates_matrix_world",
        "roll axis Rz(ψ) e_x: forgets the pitch",
        """
def euler_rates_matrix_world(yaw, pitch):
    cy, sy = np.cos(yaw), np.sin(yaw)
    return np.array([[0.0, -sy, cy], [0.0, cy, sy], [1.0, 0.0, 0.0]])
""",
        hint="gives at pitch 0",
        public_hint="gives at pitch 0",
    ),
    Mistake(
        "world_rates_ignores_yaw",
        "euler_rates_matrix_world",
        "forgets the yaw: E_w at ψ = 0",
        """
def euler_rates_matrix_world(yaw, pitch):
    cp, sp = np.cos(pitch), np.sin(pitch)
    return np.array([[0.0, 0.0, cp], [0.0, 1.0, 0.0], [1.0, 0.0, -sp]])
""",
        hint="give at yaw 0",
        public_hint="give at yaw 0",
    ),
    Mistake(
        "world_rates_reversed_columns",
        "euler_rates_matrix_world",
        "columns in the order roll, pitch, yaw",
        """
def euler_rates_matrix_world(yaw, pitch):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    return np.array([[cy * cp, -sy, 0.0], [sy * cp, cy, 0.0], [-sp, 0.0, 1.0]])
""",
        hint="the columns go in the order of the rates",
        public_hint="the columns go in the order of the rates",
    ),
]

ALTERNATIVES = [
    Alternative(
        "world_rates_as_R_E",
        "euler_rates_matrix_world",
        "R E with the roll set to 0 (E_w does not need it)",
        """
def euler_rates_matrix_world(yaw, pitch):
    cy, sy = np.cos(yaw), np.sin(yaw)
    cp, sp = np.cos(pitch), np.sin(pitch)
    R = np.array([[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]]) @ np.array([[cp, 0.0, sp], [0.0, 1.0, 0.0],
                                                                             [-sp, 0.0, cp]])
    E = np.array([[-sp, 0.0, 1.0], [0.0, 1.0, 0.0], [cp, 0.0, 0.0]])
    return R @ E
""",
    ),
]
