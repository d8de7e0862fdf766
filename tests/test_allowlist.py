"""The student's own work by allow-list (issue #43, item 4).

Each exercise states what an answer may use (``coursekit.contracts.allowance_for``: numpy, math, the
small standard helpers, the student's own functions, and the course tools its lesson's text uses);
``coursekit.watching.watch_call`` refuses anything else by construction, whatever library it comes
from. Oracles: answers that hand the work to scipy's ``expm``, a scipy ``Rotation`` method, a made-up
"next library", ``importlib``, an import inside the function, a helper that calls scipy, the
student's own other exercise that does this one's job or comes later in the lesson, a thread, a Jacobian read off
its definition with the Exp and Log its exercise may not call: each is refused with its one line,
in the check cell (in this process) and through the real sandbox (the hidden suite). Answers that use
numpy only, math, their own helpers and earlier exercises, and coursekit.lie where the lesson allows
it pass; every reference answer and every correct alternative pass under their own allowance
(``tests/test_alternatives.py`` and ``tests/test_reference_and_stubs.py`` run them with the guard on).
"""

import sys
import textwrap

import numpy as np
import pytest

from coursekit.contracts import DELEGATED_HINT, allowance_for, guard_for, refusal
from coursekit.watching import watch_call
from public_runner import run_public_checks
from support import THIS_COURSE, build_submission, grade

EXP_SO3_TAIL = """
    return R
"""

# (exercise, answer-cell source, what the one line must name)
REFUSED = {
    "scipy_expm": (
        "exp_so3",
        "from scipy.linalg import expm\n\ndef exp_so3(w):\n    return expm(hat(w))\n",
        "exp_so3 called scipy.linalg.expm",
    ),
    "scipy_rotation_method": (
        "exp_so3",
        "from scipy.spatial.transform import Rotation\n\n"
        "def exp_so3(w):\n    return Rotation.from_rotvec(np.asarray(w, dtype=float)).as_matrix()\n",
        "exp_so3 called scipy.spatial.transform.Rotation.from_rotvec",
    ),
    "next_library": (
        "exp_so3",
        # a library of rotations nobody has listed yet: a module of its own, imported by the notebook
        "import sys, types\n"
        "rotlib = types.ModuleType('rotlib')\n"
        "exec('import numpy as np\\nfrom scipy.linalg import expm\\n'\n"
        "     'def exp_map(w):\\n    w = np.asarray(w, dtype=float)\\n'\n"
        "     '    return expm(np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]]))\\n', rotlib.__dict__)\n"
        "sys.modules['rotlib'] = rotlib\n"
        "from rotlib import exp_map\n\n"
        "def exp_so3(w):\n    return exp_map(w)\n",
        "exp_so3 called rotlib.exp_map",
    ),
    "importlib": (
        "exp_so3",
        "import importlib\n\ndef exp_so3(w):\n    return importlib.import_module('scipy.linalg').expm(hat(w))\n",
        "exp_so3 called importlib.import_module",
    ),
    "import_inside": (
        "exp_so3",
        "def exp_so3(w):\n    import scipy.linalg\n    return scipy.linalg.expm(hat(w))\n",
        "exp_so3 imported scipy.linalg",
    ),
    "helper_calls_scipy": (
        "exp_so3",
        "from scipy.linalg import expm\n\ndef _matrix_exponential(W):\n    return expm(W)\n\n"
        "def exp_so3(w):\n    return _matrix_exponential(hat(w))\n",
        "exp_so3 called scipy.linalg.expm",
    ),
    "own_exercise_doing_the_job": (
        "axis_from_eigen",
        "def axis_from_eigen(R):\n    w = log_so3(R)\n    return w / np.linalg.norm(w)\n",
        "axis_from_eigen called your log_so3",
    ),
    # a later exercise builds on this one: calling it skips this one's step, whichever exercise it is
    "own_later_exercise": (
        "quat_power",
        "def quat_power(q, t):\n    return quat_slerp(np.array([1.0, 0.0, 0.0, 0.0]), q, t)\n",
        "quat_power called your quat_slerp",
    ),
    "own_later_exercise_through_a_helper": (
        "exp_series",
        "def _closed_form(W):\n    return exp_so3(vee(W))\n\n"
        "def exp_series(W, n_terms=20):\n    return _closed_form(np.asarray(W, dtype=float))\n",
        "exp_series called your exp_so3",
    ),
    "own_rotation_read_off": (
        "quat_to_matrix",
        "def quat_to_matrix(q):\n    return np.column_stack([quat_rotate(q, e) for e in np.eye(3)])\n",
        "quat_to_matrix called your quat_rotate",
    ),
    "own_product_matrices": (
        "quat_to_matrix",
        "def quat_to_matrix(q):\n    return (quat_left(q) @ quat_right(quat_conjugate(q)))[1:, 1:]\n",
        "quat_to_matrix called your quat_left",
    ),
    # the Jacobian of inverting is exactly linear in d: Log of its definition at unit turns returns it, no derivation
    "definition_evaluated": (
        "jacobian_of_inverse",
        "def jacobian_of_inverse(R):\n    R = np.asarray(R, dtype=float)\n"
        "    return np.column_stack([Log(R @ (R @ Exp(e)).T) for e in np.eye(3)])\n",
        "jacobian_of_inverse called coursekit.lie.Exp",
    ),
    # a ufunc is called without any profile event: it is judged where the answer names it
    "scipy_special_ufunc": (
        "exp_so3",
        "import scipy.special\n\ndef exp_so3(w):\n    w = np.asarray(w, dtype=float)\n    theta = np.linalg.norm(w)\n"
        "    if theta < 1e-8:\n        return np.eye(3) + hat(w)\n    K = hat(w / theta)\n"
        "    return np.eye(3) + np.sin(theta) * K - scipy.special.cosm1(theta) * (K @ K)\n",
        "exp_so3 called scipy.special.cosm1",
    ),
    # numpy's own kernel of np.linalg.inv (a gufunc), where the page prints V⁻¹ and asks for V
    "inverse_kernel": (
        "exp_se3",
        "from coursekit.lie import Exp, skew\n\ndef exp_se3(xi):\n"
        "    xi = np.asarray(xi, dtype=float).reshape(6)\n    rho, phi = xi[:3], xi[3:]\n"
        "    theta = np.linalg.norm(phi)\n    W = skew(phi)\n"
        "    c = 1 / 12 if theta < 1e-3 else (1 - theta * np.sin(theta) / (2 * (1 - np.cos(theta)))) / theta**2\n"
        "    V = np.linalg._umath_linalg.inv(np.eye(3) - 0.5 * W + c * (W @ W))\n"
        "    T = np.eye(4)\n    T[:3, :3] = Exp(phi)\n    T[:3, 3] = V @ rho\n    return T\n",
        "exp_se3 called numpy.linalg.inv",
    ),
    # the same kernel fetched by a computed name, which no code names and no profile event shows being called:
    # it is replaced by a stand-in whose calls the watch sees (coursekit.watching._put_stand_ins)
    "inverse_kernel_by_computed_name": (
        "exp_se3",
        "from coursekit.lie import Exp, skew\n\ndef exp_se3(xi):\n"
        "    xi = np.asarray(xi, dtype=float).reshape(6)\n    rho, phi = xi[:3], xi[3:]\n"
        "    theta = np.linalg.norm(phi)\n    W = skew(phi)\n"
        "    c = 1 / 12 if theta < 1e-3 else (1 - theta * np.sin(theta) / (2 * (1 - np.cos(theta)))) / theta**2\n"
        "    kernels = getattr(np.linalg, '_umath' + '_linalg')\n"
        "    V = getattr(kernels, 'in' + 'v')(np.eye(3) - 0.5 * W + c * (W @ W))\n"
        "    T = np.eye(4)\n    T[:3, :3] = Exp(phi)\n    T[:3, 3] = V @ rho\n    return T\n",
        "exp_se3 called numpy.linalg.inv",
    ),
    "ufunc_by_computed_name": (
        "exp_so3",
        "import scipy.special\n\ndef exp_so3(w):\n    w = np.asarray(w, dtype=float)\n    theta = np.linalg.norm(w)\n"
        "    if theta < 1e-8:\n        return np.eye(3) + hat(w)\n    K = hat(w / theta)\n"
        "    one_minus_cos = -vars(scipy)['spe' + 'cial'].cosm1(theta)\n"
        "    return np.eye(3) + np.sin(theta) * K + one_minus_cos * (K @ K)\n",
        "exp_so3 called scipy.special.cosm1",
    ),
    "ufunc_stored_in_a_container": (
        "exp_so3",
        "import scipy.special\nTOOLS = {'c': getattr(scipy.special, 'cos' + 'm1')}\n\n"
        "def exp_so3(w):\n    w = np.asarray(w, dtype=float)\n    theta = np.linalg.norm(w)\n"
        "    if theta < 1e-8:\n        return np.eye(3) + hat(w)\n    K = hat(w / theta)\n"
        "    return np.eye(3) + np.sin(theta) * K - TOOLS['c'](theta) * (K @ K)\n",
        "exp_so3 called scipy.special.cosm1",
    ),
    "thread": (
        "exp_so3",
        "import threading\nfrom scipy.linalg import expm\n\ndef exp_so3(w):\n"
        "    out = []\n    worker = threading.Thread(target=lambda: out.append(expm(hat(w))))\n"
        "    worker.start()\n    worker.join()\n    return out[0]\n",
        "exp_so3 called threading.Thread",
    ),
}

ALLOWED = {
    "numpy_only": ("exp_so3", None),  # the reference
    "math_and_own_helper": (
        "exp_so3",
        "import math\n\ndef _coefficients(theta):\n"
        "    if theta < 1e-4:\n        return 1 - theta**2 / 6, 0.5 - theta**2 / 24\n"
        "    return math.sin(theta) / theta, (1 - math.cos(theta)) / theta**2\n\n"
        "def exp_so3(w):\n    w = np.asarray(w, dtype=float)\n    W = hat(w)\n"
        "    a, b = _coefficients(float(np.linalg.norm(w)))\n    return np.eye(3) + a * W + b * (W @ W)\n",
    ),
    "earlier_exercise": (
        "quat_inverse",
        "def quat_inverse(q):\n    q = np.asarray(q, dtype=float)\n    return quat_conjugate(q) / np.dot(q, q)\n",
    ),
    "coursekit_lie_where_the_lesson_uses_it": (
        "boxplus_right",
        "from coursekit.lie import Exp\n\ndef boxplus_right(R, delta):\n"
        "    return np.asarray(R, dtype=float) @ Exp(np.asarray(delta, dtype=float))\n",
    ),
}


def _reference(exercise):
    from support import references

    return references()[exercise]


# --- in this process: the allowance and the tracer -------------------------------------------------------


def _main(source):
    namespace = {"__name__": "__main__", "np": np}
    exec(compile(textwrap.dedent(source), "<notebook cell>", "exec"), namespace)
    return namespace


def test_the_allowance_is_stated_per_exercise():
    assert "numpy" in allowance_for("exp_so3", "03").modules
    assert "coursekit.lie" not in allowance_for("exp_so3", "03").modules
    assert "coursekit.lie" in allowance_for("boxplus_right", "06").modules
    assert not any(m.startswith("scipy") for m in allowance_for("exp_se3", "07").modules)
    assert "scipy.spatial.transform" in allowance_for("integrate_gyro", "09").modules
    # the own functions off the list: the lesson's later exercises, then the earlier ones that do the job
    assert allowance_for("axis_from_eigen", "03").own == ("body_angular_velocity", "log_so3", "axis_angle")
    assert allowance_for("hat", "03").own[:2] == ("vee", "bracket")
    assert allowance_for("body_angular_velocity", "03").own == ()
    assert allowance_for("quat_inverse", "04").own[0] == "quat_from_axis_angle"
    assert "quat_conjugate" not in allowance_for("quat_inverse", "04").own
    assert guard_for("hat", "03") == ("allowance:hat:03", "coursekit.lie.skew")
    line = refusal("exp_so3", ["scipy.linalg._matfuncs.expm"], "03")
    assert line == (
        "exp_so3 called scipy.linalg.expm: an answer to exp_so3 may use numpy, math and your own functions "
        "except later exercises (see the start page)"
    )
    assert DELEGATED_HINT.startswith("write the exercise with numpy yourself")  # the mistakes' hint substring


def test_a_module_written_to_disk_and_imported_is_refused(tmp_path, monkeypatch):
    (tmp_path / "nextlib.py").write_text("import numpy as np\ndef turn(w):\n    return np.eye(3)\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    namespace = _main("from nextlib import turn\ndef exp_so3(w):\n    return turn(w)\n")
    _, seen = watch_call(namespace["exp_so3"], ([0.1, 0.2, 0.3],), forbidden=guard_for("exp_so3", "03"))
    assert seen.used == ["nextlib.turn"]
    sys.modules.pop("nextlib", None)


def test_an_import_inside_the_call_is_refused():
    namespace = _main("def exp_so3(w):\n    import scipy.linalg as L\n    return L.expm(np.zeros((3, 3)))\n")
    _, seen = watch_call(namespace["exp_so3"], ([0.1, 0.2, 0.3],), forbidden=guard_for("exp_so3", "03"))
    assert seen.used[:2] == ["import scipy.linalg", "scipy.linalg._matfuncs.expm"]
    assert refusal("exp_so3", seen.used, "03").startswith(
        "exp_so3 imported scipy.linalg, called scipy.linalg.expm: an answer to exp_so3 may use"
    )
    import builtins

    assert builtins.__import__.__module__ != "coursekit.watching"  # the guard is gone after the call


def test_allowed_imports_and_calls_go_through():
    namespace = _main(
        "def f(w):\n    import math, functools, itertools\n    from numpy import linalg\n"
        "    return functools.reduce(lambda a, b: a + b, [math.cos(x) for x in w]) + linalg.norm(w)\n"
    )
    _, seen = watch_call(namespace["f"], ([0.1, 0.2, 0.3],), forbidden=guard_for("exp_so3", "03"))
    assert seen.used == [] and not seen.tampered


def test_kernels_stood_in_for_still_work_for_the_libraries_that_use_them():
    """After a watched call has put its stand-ins in place (numpy's inverse kernels for exp_se3, scipy's ufuncs
    and LAPACK routines for exp_so3), the libraries' own functions that call those kernels give the same numbers,
    inside an allowed answer (not refused) and outside any watched call."""
    import scipy.linalg
    import scipy.special

    A = np.array([[4.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 2.0]])
    before = (np.linalg.det(A), np.linalg.eigvalsh(A), scipy.special.cosm1(0.3), scipy.linalg.solve(A, np.ones(3)))
    namespace = _main("def f(A):\n    return np.linalg.det(A), np.linalg.eigvalsh(A), np.linalg.svd(A)[1]\n")
    for exercise, lesson in (("exp_se3", "07"), ("exp_so3", "03")):
        value, seen = watch_call(namespace["f"], (A,), forbidden=guard_for(exercise, lesson))
        assert seen.used == [] and not seen.tampered, (exercise, seen.used)
        assert value[0] == pytest.approx(before[0]) and np.allclose(value[1], before[1])
    assert type(np.linalg._umath_linalg.inv).__name__ == "inv", "the inverse kernel has no stand-in: test nothing"
    after = (np.linalg.det(A), np.linalg.eigvalsh(A), scipy.special.cosm1(0.3), scipy.linalg.solve(A, np.ones(3)))
    for old, new in zip(before, after):
        np.testing.assert_allclose(new, old, rtol=1e-15)


def test_callbacks_handed_to_numpy_count_and_functions_handed_in_are_the_callers():
    import scipy.linalg

    namespace = _main("import scipy.linalg\ndef f(X):\n    return np.apply_along_axis(scipy.linalg.norm, 1, X)\n")
    _, seen = watch_call(namespace["f"], (np.eye(3),), forbidden=guard_for("exp_so3", "03"))
    assert seen.used and seen.used[0].endswith("norm")
    # a function the caller hands in (a check's own function, a probe) is the caller's, not a library
    namespace = _main("def apply(g, x):\n    return g(x)\n")
    _, seen = watch_call(namespace["apply"], (scipy.linalg.norm, np.ones(3)), forbidden=guard_for("exp_so3", "03"))
    assert seen.used == []
    # printing is free
    namespace = _main("def f(x):\n    print('x is', x)\n    return x\n")
    _, seen = watch_call(namespace["f"], (np.ones(2),), forbidden=guard_for("exp_so3", "03"))
    assert seen.used == []


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_the_check_cell_refuses_with_its_line(case):
    exercise, source, named = REFUSED[case]
    passed, printed = run_public_checks(THIS_COURSE, exercise, source)
    assert not passed
    assert named in printed, printed
    lesson = THIS_COURSE.catalog.exercise(exercise).lesson
    assert (
        f"an answer to {exercise} may use {allowance_for(exercise, lesson).describe()} (see the start page)" in printed
    )


@pytest.mark.parametrize("case", sorted(ALLOWED))
def test_the_check_cell_accepts_allowed_answers(case):
    exercise, source = ALLOWED[case]
    passed, printed = run_public_checks(THIS_COURSE, exercise, source or _reference(exercise))
    assert passed, printed


# --- through the real sandbox: the hidden suite ----------------------------------------------------------


def _graded(tmp_path, slot, exercise, source):
    lesson = THIS_COURSE.catalog.exercise(exercise).lesson
    folder = build_submission(tmp_path / "student", {exercise: source}, lessons=(lesson,))
    result = grade(folder, lessons=(lesson,), slot=slot)
    return {e.name: e for e in result.exercises}


@pytest.mark.parametrize("case", sorted(REFUSED))
def test_the_hidden_suite_refuses_with_its_line(case, tmp_path, warm_slot):
    exercise, source, named = REFUSED[case]
    graded = _graded(tmp_path, warm_slot, exercise, source)
    checks = graded[exercise].checks
    assert not any(c.passed for c in checks), [(c.description, c.reason) for c in checks if c.passed]
    lines = [f"{c.reason} {c.hint}" for c in checks]
    assert any(named in line and "see the start page" in line for line in lines), lines[:3]
    others = [c for name, e in graded.items() if name != exercise for c in e.checks if not c.passed]
    assert not others, [(c.exercise, c.reason) for c in others][:3]


@pytest.mark.parametrize("case", sorted(ALLOWED))
def test_the_hidden_suite_accepts_allowed_answers(case, tmp_path, warm_slot):
    exercise, source = ALLOWED[case]
    graded = _graded(tmp_path, warm_slot, exercise, source or _reference(exercise))
    failed = [(c.description, c.reason) for c in graded[exercise].checks if not c.passed]
    assert not failed, failed
