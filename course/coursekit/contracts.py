"""Two promises every exercise makes besides its value, as the course states them.

- **Its arguments are left unchanged.** ``rotate_point(R, p)`` must not
  overwrite ``p``: a later cell that reuses ``p`` would print wrong values.
- **It is your own implementation.** Where an exercise asks you to write a map
  (``exp_so3``, ``quat_multiply``, ``matrix_to_euler_zyx``), calling the library
  version of it answers a different question. The rule is an allow-list:
  :func:`allowance_for` says what an answer may call or import (numpy, math, the
  small standard helpers, the student's own functions, and the course tools its
  lesson's text uses); anything else is refused, whatever library it comes from.
  Within that, :data:`FORBIDDEN` lists the library functions that do the
  exercise's own job (``coursekit.lie.ExpSE3`` for ``exp_se3`` in lesson 07). Of the
  student's own functions, the answers to the lesson's *later* exercises are off the list
  (they build on this one, so calling one would skip its step), and :data:`OWN_FORBIDDEN`
  names the few earlier ones that do this exercise's job.

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

from .exercise_contracts import later_exercises

__all__ = [
    "FORBIDDEN",
    "forbidden_for",
    "CHANGED_HINT",
    "DELEGATED_HINT",
    "INVERTED_HINT",
    "delegated_hint",
    "Allowance",
    "allowance_for",
    "guard_for",
    "refusal",
]

SCIPY_ROTATIONS = ("scipy.spatial.transform",)  # Rotation, Slerp, RotationSpline
MATRIX_FUNCTIONS = ("scipy.linalg.expm", "scipy.linalg.logm", "scipy.linalg.expm_frechet")
EXP_LOG = ("coursekit.lie.Exp", "coursekit.lie.Log")
# numpy's inverses and solvers: where the inverse is the exercise's job (pose_inverse) or the page prints the
# inverse of an exercise's answer (J_r⁻¹ in lesson 06, V⁻¹ in lesson 07), inverting numerically skips the derivation
# (and their kernels, numpy.linalg._umath_linalg's gufuncs, which no profile event shows being called:
# coursekit.watching judges them where the code names them)
INVERSES = tuple(
    f"numpy.linalg.{name}" for name in ("inv", "solve", "pinv", "lstsq", "tensorinv", "tensorsolve", "matrix_power")
) + ("numpy.linalg._umath_linalg",)

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
    # lesson 06: the right Jacobian is the job (the library's SE(3) maps carry the SO(3) Jacobian inside them)
    "right_jacobian_so3": ("coursekit.lie.JrSE3", "coursekit.lie.ExpSE3", "coursekit.lie.LogSE3") + MATRIX_FUNCTIONS + INVERSES,
    "right_jacobian_inv_so3": ("coursekit.lie.JrSE3", "coursekit.lie.ExpSE3", "coursekit.lie.LogSE3") + MATRIX_FUNCTIONS,
    # the Jacobians of composing and inverting are exactly linear in d, so Log of their definition at unit turns
    # would return them without a derivation; neither answer needs Exp or Log
    "jacobians_of_compose": EXP_LOG,
    "jacobian_of_inverse": EXP_LOG,
    # lesson 07: poses (the rotation part may come from Exp; V(phi) and the assembly are the job)
    "pose_inverse": ("coursekit.lie.ExpSE3", "coursekit.lie.LogSE3") + INVERSES,  # the inverse is the job
    "exp_se3": ("coursekit.lie.ExpSE3", "coursekit.lie.LogSE3", "coursekit.lie.JrSE3") + MATRIX_FUNCTIONS + INVERSES,
    "log_se3": ("coursekit.lie.ExpSE3", "coursekit.lie.LogSE3", "coursekit.lie.JrSE3") + MATRIX_FUNCTIONS,
    # lesson 07, section 10: the adjoint and the Jacobian of Exp are the job (Ad_Exp(ξ) = Jr(-ξ) Jr(ξ)⁻¹, and
    # Jr(ξ) is the integral of Ad_Exp(-sξ) over s in [0, 1], so the library's SE(3) maps compute either one)
    "adjoint_se3": ("coursekit.lie.AdSE3", "coursekit.lie.JrSE3", "coursekit.lie.LogSE3"),
    "right_jacobian_se3": ("coursekit.lie.JrSE3", "coursekit.lie.AdSE3", "coursekit.lie.ExpSE3", "coursekit.lie.LogSE3")
    + MATRIX_FUNCTIONS,
    # lesson 04, section 14: q^t is the job (scipy's Slerp and Rotation powers do it)
    "quat_power": SCIPY_ROTATIONS,
}

CHANGED_HINT = (
    "work on a copy, e.g. `p = np.array(p, dtype=float)`, and build the result in a new array; "
    "`x /= n`, `x[0] = ...` and `x.sort()` change the caller's array"
)
DELEGATED_HINT = (
    "write the exercise with numpy yourself: an answer may call numpy, math, the small standard "
    "helpers and your own functions, plus the course tools its lesson's text uses (the start "
    "page says which)"
)


INVERTED_HINT = (
    "derive the answer itself, from your own closed form and numpy's arithmetic: a general inverse or solver "
    "finds the numbers without the derivation"
)


def delegated_hint(used):
    """The hint for a refused answer, from what it called (names, or the refusal line itself).

    >>> delegated_hint(["numpy.linalg._linalg.inv"]) == INVERTED_HINT
    True
    >>> delegated_hint("exp_so3 called scipy.linalg.expm: ...") == DELEGATED_HINT
    True
    """
    text = used if isinstance(used, str) else " ".join(used)
    return INVERTED_HINT if "numpy.linalg." in text else DELEGATED_HINT


def forbidden_for(exercise):
    """The entries ``exercise`` must not call (a tuple, empty for most exercises)."""
    return FORBIDDEN.get(exercise, ())


# What an answer may use: the allow-list. Every call made from notebook code while an exercise runs
# (and every import it makes) must land in one of these modules, in the student's own notebook code,
# or in a function the caller handed in as an argument; anything else is refused, whatever library
# it comes from (scipy, transforms3d, a module of one's own, importlib). Libraries' own internal
# calls are free. Found by running every reference answer and every correct alternative under a
# recording tracer and by reading the masters' text: only lessons 06-09 use coursekit.lie in their
# answers (their setup cells import it), only lesson 09's text uses scipy.
PLAIN = (
    "numpy",  # all of it, numpy.linalg and numpy.random included
    "math",
    "cmath",
    "builtins",
    # small standard helpers an answer may reasonably call; none of them does a rotation's work
    "functools",
    "itertools",
    "operator",
    "copy",
    "numbers",
    "warnings",
    "collections",
    "dataclasses",
    "typing",
    "abc",
    "enum",
    "contextlib",
    "heapq",
    "bisect",
    "fractions",
    "decimal",
    "statistics",
    "string",
    "re",
    "types",
    # the C halves of the same helpers (their methods report these modules)
    "_operator",
    "_functools",
    "_collections",
    "_collections_abc",
    "_heapq",
    "_bisect",
    "_decimal",
    "_pydecimal",
    "_warnings",
    "_abc",
    "copyreg",
)
LIE_FROM_LESSON = "06"  # lessons 06-09 build on coursekit.lie (FORBIDDEN still keeps each exercise's own job)
LESSON_EXTRAS = {"09": ("scipy.spatial.transform", "scipy.linalg", "scipy.stats")}  # lesson 09's text uses them

# The student's own functions: an answer may call its lesson's earlier exercises and any helper of the
# notebook, never a later exercise (later exercises build on earlier ones: slerp contains q^t, J_r⁻¹ inverts
# J_r, Rodrigues' exp_so3 sums exp_series' series), whichever it is. Earlier exercises are free, except
# these, which do this exercise's own job.
OWN_FORBIDDEN = {
    "axis_from_eigen": ("log_so3", "axis_angle"),  # the axis must come from the eigenvector
    "quat_to_matrix": ("quat_rotate", "quat_left", "quat_right"),  # R(q) is to be written out, not evaluated
}


class Allowance:
    """What an answer to ``exercise`` (of ``lesson``) may call: ``modules`` (names, each with its
    submodules), every function of the notebook except those in ``own`` (the lesson's later exercises,
    then the earlier ones of :data:`OWN_FORBIDDEN`)."""

    def __init__(self, exercise, lesson, modules, own):
        self.exercise, self.lesson, self.modules, self.own = exercise, lesson, tuple(modules), tuple(own)

    def describe(self):
        """The allowance in words, as the feedback line says it."""
        forbidden = forbidden_for(self.exercise)

        def shown(module):  # "coursekit.lie (without Exp and Log)" when the exercise may not call some of it
            names = [f[len(module) + 1 :] for f in forbidden if f.startswith(module + ".") and "." not in f[len(module) + 1 :]]
            return f"{module} (without {_in_words(names)})" if names else module

        extra = [shown(name) for name in self.modules if name.startswith(("coursekit", "scipy"))]
        numpy = "numpy"
        if set(INVERSES) <= set(forbidden_for(self.exercise)):
            numpy = "numpy (without np.linalg's inverses and solvers)"
        tools = ", ".join([numpy, "math"] + extra)
        later = later_exercises(self.exercise)
        barred = ["later exercises"] if later else []
        barred += [name for name in self.own if name not in later]
        if not barred:
            return f"{tools} and your own functions"
        return f"{tools} and your own functions except {' and '.join(barred)}"

    def __repr__(self):
        return (
            f"Allowance({self.exercise!r}, {self.lesson!r}, +{list(self.modules[len(PLAIN) :])}, own-{list(self.own)})"
        )


def _in_words(names):
    """``["A", "B", "C"]`` → ``"A, B and C"``."""
    return names[0] if len(names) == 1 else ", ".join(names[:-1]) + " and " + names[-1]


def allowance_for(exercise, lesson=""):
    """The :class:`Allowance` of ``exercise`` in ``lesson`` (``"03"``).

    >>> allowance_for("body_angular_velocity", "03").describe()
    'numpy, math and your own functions'
    >>> allowance_for("pose_compose", "07").describe()
    'numpy, math, coursekit.lie and your own functions except later exercises'
    >>> allowance_for("exp_se3", "07").describe()  # doctest: +NORMALIZE_WHITESPACE
    "numpy (without np.linalg's inverses and solvers), math, coursekit.lie (without ExpSE3, LogSE3 and JrSE3)
    and your own functions except later exercises"
    >>> allowance_for("jacobian_of_inverse", "06").describe()
    'numpy, math, coursekit.lie (without Exp and Log) and your own functions'
    >>> allowance_for("axis_from_eigen", "03").describe()
    'numpy, math and your own functions except later exercises and log_so3 and axis_angle'
    """
    modules = PLAIN
    if str(lesson) >= LIE_FROM_LESSON:
        modules += ("coursekit.lie",)
    modules += LESSON_EXTRAS.get(str(lesson), ())
    return Allowance(exercise, str(lesson), modules, later_exercises(exercise) + OWN_FORBIDDEN.get(exercise, ()))


def guard_for(exercise, lesson):
    """What the check cells and the grader hand :func:`coursekit.watching.watch_call` for
    ``exercise``: its allowance and its :data:`FORBIDDEN` entries.

    >>> guard_for("hat", "03")
    ('allowance:hat:03', 'coursekit.lie.skew')
    """
    return (f"allowance:{exercise}:{lesson}",) + forbidden_for(exercise)


def refusal(exercise, used, lesson=""):
    """The one line a refused answer gets, in the check cell and in the grader's feedback.

    >>> done, rule = refusal("exp_so3", ["scipy.linalg._matfuncs.expm"], "03").split(": ")
    >>> done
    'exp_so3 called scipy.linalg.expm'
    >>> rule
    'an answer to exp_so3 may use numpy, math and your own functions except later exercises (see the start page)'
    """
    used = [used] if isinstance(used, str) else list(used)
    done = ", ".join(_shown(name) for name in used)
    return (
        f"{exercise} {done}: an answer to {exercise} may use "
        f"{allowance_for(exercise, lesson).describe()} (see the start page)"
    )


def _shown(name):
    """``"scipy.linalg._matfuncs.expm"`` → ``"called scipy.linalg.expm"`` (private modules left out);
    ``"import scipy"`` → ``"imported scipy"``; ``"your log_so3"`` → ``"called your log_so3"``."""
    if name.startswith("import "):
        return "imported " + name[len("import ") :]
    if name == "sys.setprofile":
        return "switched the course's watching off (sys.setprofile)"
    if not name.startswith("your "):
        parts = name.split(".")
        name = ".".join([part for part in parts[:-1] if not part.startswith("_")] + parts[-1:])
    return "called " + name
