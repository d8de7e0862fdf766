"""Typical mistakes for lesson 07, section 8: the relative pose (the colleague's bug and its relatives)."""

from . import Alternative, Mistake

MISTAKES = [
    Mistake(
        "relative_pose_world_difference",
        "relative_pose",
        "T_wb T_wa⁻¹: the colleague's bug",
        """
def relative_pose(T_wa, T_wb):
    return np.asarray(T_wb, dtype=float) @ np.linalg.inv(np.asarray(T_wa, dtype=float))
""",
        hint="what the colleague's function returns",
        public_hint="what the colleague's function returns",
        classic=True,
    ),
    Mistake(
        "relative_pose_transposed",
        "relative_pose",
        "T_waᵀ T_wb: the transpose as the inverse",
        """
def relative_pose(T_wa, T_wb):
    return np.asarray(T_wa, dtype=float).T @ np.asarray(T_wb, dtype=float)
""",
        hint="not its transpose",
        public_hint="not its transpose",
    ),
    Mistake(
        "relative_pose_reversed",
        "relative_pose",
        "T_wb⁻¹ T_wa: a seen from b",
        """
def relative_pose(T_wa, T_wb):
    return np.linalg.inv(np.asarray(T_wb, dtype=float)) @ np.asarray(T_wa, dtype=float)
""",
        hint="that is T_ba",
        public_hint="that is T_ba",
    ),
    Mistake(
        "relative_pose_unrotated_shift",
        "relative_pose",
        "t_wb - t_wa left in world axes",
        """
def relative_pose(T_wa, T_wb):
    T_wa = np.asarray(T_wa, dtype=float)
    T_wb = np.asarray(T_wb, dtype=float)
    T_ab = np.eye(4)
    T_ab[:3, :3] = T_wa[:3, :3].T @ T_wb[:3, :3]
    T_ab[:3, 3] = T_wb[:3, 3] - T_wa[:3, 3]
    return T_ab
""",
        hint="compare the translation columns with T_wa turned",
        public_hint="compare the translation columns with T_wa turned",
    ),
    Mistake(
        "relative_pose_list_slices",
        "relative_pose",
        "T[:3, :3] on the inputs as given: a nested list takes no 2-D slice",
        """
def relative_pose(T_wa, T_wb):
    R_aw = T_wa[:3, :3].T
    T_ab = np.eye(4)
    T_ab[:3, :3] = R_aw @ T_wb[:3, :3]
    T_ab[:3, 3] = R_aw @ (T_wb[:3, 3] - T_wa[:3, 3])
    return T_ab
""",
        hint="lists have no .T and @ does not work on them",
        public_hint="lists have no .T and @ does not work on them",
    ),
]

ALTERNATIVES = [
    Alternative(
        "relative_pose_solve",
        "relative_pose",
        "solves T_wa X = T_wb with np.linalg.solve",
        """
def relative_pose(T_wa, T_wb):
    X = np.linalg.solve(np.asarray(T_wa, dtype=float), np.asarray(T_wb, dtype=float))
    X[3] = [0.0, 0.0, 0.0, 1.0]
    return X
""",
    ),
]
