"""Which library functions an exercise must not hand its work to.

Where an exercise asks the student to write a map themselves (``exp_so3``,
``quat_multiply``), calling the library version of it answers a different
question. The grader sends each exercise's list with every call of it; the
sandbox watches the call (:mod:`coursekit.watching`) and a call that used one
of them directly from the student's code earns the exercise no points, with
the reason. Later lessons keep using the library freely: only the exercise
whose job it is appears here.

An entry is a module or package (``"coursekit.lie"``: every function in it)
or one function (``"scipy.linalg.expm"``).
"""

ROTATION_LIBRARIES = ("coursekit.lie", "scipy.spatial.transform")
MATRIX_FUNCTIONS = ("scipy.linalg.expm", "scipy.linalg.logm", "scipy.linalg.expm_frechet")

FORBIDDEN = {
    "hat": ("coursekit.lie.skew",),
    "vee": ("coursekit.lie.unskew",),
    "exp_series": MATRIX_FUNCTIONS,
    "exp_so3": ROTATION_LIBRARIES + MATRIX_FUNCTIONS,
    "log_so3": ROTATION_LIBRARIES + MATRIX_FUNCTIONS,
    "axis_angle": ROTATION_LIBRARIES + MATRIX_FUNCTIONS,
    "quat_multiply": ("coursekit.lie.quat_product", "scipy.spatial.transform"),
    "quat_to_matrix": ("scipy.spatial.transform",),
    "matrix_to_quat": ("scipy.spatial.transform",),
    "quat_slerp": ("scipy.spatial.transform",),
    "euler_zyx_to_matrix": ("scipy.spatial.transform",),
    "matrix_to_euler_zyx": ("scipy.spatial.transform",),
}


def forbidden_for(exercise):
    """The entries ``exercise`` must not call (a tuple, empty for most exercises)."""
    return FORBIDDEN.get(exercise, ())
