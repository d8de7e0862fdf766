"""Two promises every exercise makes besides its value, as the course states them.

- **Its arguments are left unchanged.** ``rotate_point(R, p)`` must not
  overwrite ``p``: a later cell that reuses ``p`` would print wrong values.
- **It is your own implementation.** Where an exercise asks you to write a map
  (``exp_so3``, ``quat_multiply``, ``matrix_to_euler_zyx``), calling the library
  version of it answers a different question. :data:`FORBIDDEN` lists, per
  exercise, the library functions that do its job; later lessons use them freely.

:func:`coursekit.watching.watch_call` sees both; the check cells and the
grader's sandbox use it with this list and say what they saw in the same words
(:data:`CHANGED_HINT`, :data:`DELEGATED_HINT`).

An entry of :data:`FORBIDDEN` is a module or package (``"scipy.spatial.transform"``:
every function in it, ``Rotation`` and ``Slerp`` included) or one function
(``"coursekit.lie.Exp"``, ``"scipy.linalg.expm"``).

Examples
--------
>>> forbidden_for("exp_so3")[:2]
('coursekit.lie.Exp', 'coursekit.lie.Log')
>>> forbidden_for("boxplus_right")
()
"""

__all__ = ["FORBIDDEN", "forbidden_for", "CHANGED_HINT", "DELEGATED_HINT"]

SCIPY_ROTATIONS = ("scipy.spatial.transform",)  # Rotation, Slerp, RotationSpline
MATRIX_FUNCTIONS = ("scipy.linalg.expm", "scipy.linalg.logm", "scipy.linalg.expm_frechet")
EXP_LOG = ("coursekit.lie.Exp", "coursekit.lie.Log")

# Only the functions that do the exercise's own job: exp_so3 may use a skew helper (writing
# [w]× is the hat exercise's job), euler_zyx_to_matrix may build its elementary rotations with
# Exp (its job is the z-y-x order), and lessons 06-08 build on the library throughout.
FORBIDDEN = {
    # lesson 03: so(3), exp and log
    "hat": ("coursekit.lie.skew",),
    "vee": ("coursekit.lie.unskew",),
    "exp_series": MATRIX_FUNCTIONS,
    "exp_so3": EXP_LOG + SCIPY_ROTATIONS + MATRIX_FUNCTIONS,
    "log_so3": EXP_LOG + SCIPY_ROTATIONS + MATRIX_FUNCTIONS,
    "axis_angle": EXP_LOG + SCIPY_ROTATIONS + MATRIX_FUNCTIONS,
    "axis_from_eigen": EXP_LOG + SCIPY_ROTATIONS + MATRIX_FUNCTIONS,
    # lesson 04: quaternions
    "quat_multiply": ("coursekit.lie.quat_product",) + SCIPY_ROTATIONS,
    "quat_left": ("coursekit.lie.quat_product",) + SCIPY_ROTATIONS,
    "quat_right": ("coursekit.lie.quat_product",) + SCIPY_ROTATIONS,
    "quat_conjugate": SCIPY_ROTATIONS,
    "quat_inverse": SCIPY_ROTATIONS,
    "quat_from_axis_angle": EXP_LOG + SCIPY_ROTATIONS,
    "quat_rotate": EXP_LOG + SCIPY_ROTATIONS,
    "quat_to_matrix": EXP_LOG + SCIPY_ROTATIONS,
    "matrix_to_quat": EXP_LOG + SCIPY_ROTATIONS,
    "quat_slerp": EXP_LOG + SCIPY_ROTATIONS,
    # lesson 05: Euler angles
    "euler_zyx_to_matrix": SCIPY_ROTATIONS,
    "matrix_to_euler_zyx": SCIPY_ROTATIONS,
    "euler_zyx_to_quat": SCIPY_ROTATIONS,
    "quat_to_euler_zyx": SCIPY_ROTATIONS,
    # lesson 07: poses (the rotation part may come from Exp; V(phi) and the assembly are the job)
    "exp_se3": ("coursekit.lie.ExpSE3", "coursekit.lie.LogSE3") + MATRIX_FUNCTIONS,
    "log_se3": ("coursekit.lie.ExpSE3", "coursekit.lie.LogSE3") + MATRIX_FUNCTIONS,
    # lesson 07, section 10: the adjoint and the Jacobian of Exp are the job
    "adjoint_se3": ("coursekit.lie.AdSE3",),
    "right_jacobian_se3": ("coursekit.lie.JrSE3",) + MATRIX_FUNCTIONS,
    # lesson 04, section 14: q^t is the job (scipy's Slerp and Rotation powers do it)
    "quat_power": SCIPY_ROTATIONS,
}

CHANGED_HINT = ("work on a copy, e.g. `p = np.array(p, dtype=float)`, and build the result in a new array; "
                "`x /= n`, `x[0] = ...` and `x.sort()` change the caller's array")
DELEGATED_HINT = ("write the exercise with numpy yourself; coursekit.lie and scipy's Rotation are for the "
                  "later lessons")


def forbidden_for(exercise):
    """The entries ``exercise`` must not call (a tuple, empty for most exercises)."""
    return FORBIDDEN.get(exercise, ())
