"""A call's contracts beyond its value: arguments left unchanged, and no delegation to the library.

``coursekit.watching.watch_call`` is the one definition, used by the visible checks (in the notebook's
process) and by the sandbox's worker (whose replies carry ``changed`` and ``delegated``). Oracles: a
copy taken before the call, compared bit for bit; the names of library functions entered directly from
``__main__`` code. Edge cases: arrays inside lists, keyword arguments, a NaN that stays NaN, a library
that uses the forbidden function internally (allowed), a function that switches the watching off.
"""

import sys

import numpy as np
import pytest

from autograder.sandbox.session import LessonProgram, StudentError, StudentSandbox
from coursekit.watching import watch_call
from support import THIS_COURSE


def _main(source):
    """Functions defined as notebook code is: in a namespace whose ``__name__`` is ``__main__``."""
    namespace = {"__name__": "__main__", "np": np}
    exec(compile(source, "<lesson 01 cell test>", "exec"), namespace)
    return namespace


def test_an_array_changed_in_place_is_named():
    f = _main("def normalise(q):\n    q /= np.linalg.norm(q)\n    return q")["normalise"]
    _, seen = watch_call(f, (np.array([2.0, 0.0, 0.0, 0.0]),))
    assert seen.changed == ["q"]


def test_arrays_inside_lists_and_keyword_arguments_are_watched():
    f = _main("def mean(Rs, weights=None):\n    Rs[1][0, 0] = 5.0\n    weights.append(1)\n    return Rs[0]")["mean"]
    _, seen = watch_call(f, ([np.eye(3), np.eye(3)],), {"weights": [0.5]})
    assert seen.changed == ["Rs", "weights"]


def test_a_function_that_leaves_its_arguments_alone_changes_nothing():
    f = _main("def scaled(p):\n    p = np.array(p, dtype=float)\n    p *= 2\n    return p")["scaled"]
    value, seen = watch_call(f, (np.array([1.0, np.nan, -0.0]),))
    assert seen.changed == [] and seen.used == [] and not seen.tampered
    assert np.isnan(value[1])


def test_direct_calls_into_the_library_are_delegation_and_indirect_ones_are_not():
    namespace = _main(
        "from coursekit.lie import Exp as E\n"
        "def exp_so3(w):\n    return E(w)\n"
        "def shown(w):\n    from coursekit.plotting import np as _\n    return np.eye(3)"
    )
    _, seen = watch_call(namespace["exp_so3"], ([0.1, 0.2, 0.3],), forbidden=("coursekit.lie",))
    assert seen.used == ["coursekit.lie.Exp"]
    # scipy's Rotation is called by coursekit.lie.Exp, not by the notebook: only the direct call counts
    _, seen = watch_call(namespace["exp_so3"], ([0.1, 0.2, 0.3],), forbidden=("scipy.spatial.transform",))
    assert seen.used == []
    _, seen = watch_call(namespace["shown"], ([0.1, 0.2, 0.3],), forbidden=("coursekit.lie",))
    assert seen.used == []


def test_a_single_function_is_resolved_to_where_it_lives():
    f = _main("import scipy.linalg\ndef exp_series(W, n):\n    return scipy.linalg.expm(np.asarray(W))")["exp_series"]
    _, seen = watch_call(f, (np.zeros((3, 3)), 3), forbidden=("scipy.linalg.expm",))
    assert len(seen.used) == 1 and seen.used[0].endswith(".expm")


def test_what_the_interpreter_runs_on_its_own_is_not_the_answers_call(monkeypatch):
    """A garbage-collector callback (hypothesis, loaded by the hidden suite, registers one), a library object's
    finaliser, a weak reference's callback and the closing of a library's suspended generator (a hypothesis
    generator left over from an earlier test failed CI) run inside whatever notebook frame a collection
    interrupts: none of them is the answer's call.
    Run with collections after every few allocations, inside C calls of the answer and in its own frames."""
    import gc
    import types

    library = types.ModuleType("a_library_outside_the_allowance")
    exec(
        "import sys, weakref\ncalls = []\n"
        "def note(what):\n    calls.append((what, sys.getprofile() is not None))\n"
        "def on_collection(phase, info):\n    note(phase)\n"
        "class Handle:\n    def __del__(self):\n        note('__del__')\n"
        "def walk():\n    try:\n        yield 1\n    finally:\n        note('closed')\n"
        "refs = []\n"
        "class Owner:\n    def __init__(self):\n        self.me = self\n        self.handle = Handle()\n"
        "        weakref.finalize(self, note, 'finalize')\n"
        "        refs.append(weakref.ref(self, lambda ref: note('weakref')))\n"
        "        self.walk = walk()\n        next(self.walk)\n",
        library.__dict__,
    )
    monkeypatch.setitem(sys.modules, library.__name__, library)
    answer = _main(
        "def exp_so3(w):\n    rows = [[i, [i]] for i in range(40000)]\n"
        "    return np.eye(3) + np.asarray(w, dtype=float).sum() * np.zeros((3, 3))"
    )["exp_so3"]
    threshold = gc.get_threshold()
    gc.collect()
    gc.set_threshold(20000, 1, 1)  # no collection before the watch starts; several inside the answer's loop
    gc.callbacks.append(library.on_collection)  # the interpreter's own list: a new list would not be called
    try:
        for _ in range(3):
            library.Owner()  # garbage in a cycle, with a finaliser and a __del__, for the next collection
        _, seen = watch_call(answer, ([0.1, 0.2, 0.3],), forbidden=("allowance:exp_so3:03",))
    finally:
        gc.set_threshold(*threshold)
        gc.callbacks.remove(library.on_collection)
    during = {what for what, watched in library.calls if watched}
    assert {"__del__", "finalize", "weakref", "closed", "start", "stop"} <= during, library.calls
    assert seen.used == [], seen.used
    direct = _main(
        "def exp_so3(w):\n    import a_library_outside_the_allowance as lib\n    lib.on_collection('x', {})\n"
        "    return np.eye(3)"
    )["exp_so3"]
    _, seen = watch_call(direct, ([0.0, 0.0, 0.0],), forbidden=("allowance:exp_so3:03",))
    assert any("on_collection" in name for name in seen.used), seen.used  # called by the answer: refused
    own_finaliser = _main(
        "import a_library_outside_the_allowance as lib\n"
        "class Keeper:\n    def __init__(self):\n        self.me = self\n"
        "    def __del__(self):\n        lib.note('the notebook finaliser')\n"
        "def exp_so3(w):\n    for _ in range(3):\n        Keeper()\n"
        "    rows = [[i, [i]] for i in range(40000)]\n    return np.eye(3)"
    )["exp_so3"]
    gc.set_threshold(20000, 1, 1)
    try:
        _, seen = watch_call(own_finaliser, ([0.0, 0.0, 0.0],), forbidden=("allowance:exp_so3:03",))
    finally:
        gc.set_threshold(*threshold)
    assert ("the notebook finaliser", True) in library.calls, library.calls  # run by a collection in the watch
    assert any(name.endswith(".note") for name in seen.used), seen.used  # the notebook's own code: refused


def test_a_signal_handler_is_not_the_answers_call(monkeypatch):
    """A signal handler (the grader's alarm, a library's) runs inside whatever frame the signal interrupts."""
    import signal
    import types

    library = types.ModuleType("a_library_with_a_handler")
    exec("calls = []\ndef on_alarm(number, frame):\n    calls.append(number)\n", library.__dict__)
    monkeypatch.setitem(sys.modules, library.__name__, library)
    answer = _main(
        "def exp_so3(w):\n    total = 0.0\n    for i in range(300000):\n        total += i * 1e-9\n"
        "    return np.eye(3) + 0.0 * total"
    )["exp_so3"]
    previous = signal.signal(signal.SIGALRM, library.on_alarm)
    try:
        signal.setitimer(signal.ITIMER_REAL, 0.002, 0.002)
        _, seen = watch_call(answer, ([0.0, 0.0, 0.0],), forbidden=("allowance:exp_so3:03",))
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
    assert len(library.calls) >= 3, library.calls  # the handler did run during the call
    assert seen.used == [], seen.used


def test_looking_for_unseen_calls_runs_none_of_the_notebooks_code():
    """The names an answer reaches are judged by static lookups: a notebook object's __getattr__ never runs."""
    namespace = _main(
        "looked_up = []\n"
        "class Scaler:\n    def __call__(self, x):\n        return 2.0 * x\n"
        "    def __getattr__(self, name):\n        looked_up.append(name)\n        raise AttributeError(name)\n"
        "scale = Scaler()\n"
        "def exp_so3(w):\n    return scale(np.eye(3))\n"
    )
    _, seen = watch_call(namespace["exp_so3"], ([0.1, 0.2, 0.3],), forbidden=("allowance:exp_so3:03",))
    assert seen.used == [] and namespace["looked_up"] == [], (seen.used, namespace["looked_up"])


def test_switching_the_watching_off_is_seen():
    f = _main("import sys\nfrom coursekit.lie import skew\ndef hat(w):\n    sys.setprofile(None)\n    return skew(w)")[
        "hat"
    ]
    _, seen = watch_call(f, ([1.0, 2.0, 3.0],), forbidden=("coursekit.lie.skew",))
    assert seen.tampered and seen.used == []


SOURCE = """
def rotate_point(R, p):
    p = np.asarray(p)
    p += 0.0
    p[0] = p[0] * 1.0 + 1.0
    return np.asarray(R) @ p

def exp_so3(w):
    from coursekit.lie import Exp
    return Exp(w)

def honest(R, p):
    return np.asarray(R, dtype=float) @ np.asarray(p, dtype=float)
"""


@pytest.fixture(scope="module")
def box():
    program = {"01": LessonProgram(setup="import numpy as np", cells=[("code", SOURCE)])}
    with StudentSandbox(program, THIS_COURSE.support) as sandbox:
        yield sandbox


def test_the_sandbox_reports_an_argument_changed_in_place(box):
    value = box.call("01", "rotate_point", [np.eye(3), np.array([1.0, 2.0, 3.0])])
    assert box.last_changed == ["p"] and value.tolist() == [2.0, 2.0, 3.0]
    box.call("01", "honest", [np.eye(3), np.array([1.0, 2.0, 3.0])])
    assert box.last_changed == []


def test_the_sandbox_turns_delegation_into_a_student_error(box):
    assert box.call("01", "exp_so3", [[0.0, 0.0, 0.5]]).shape == (3, 3)  # allowed when nothing is forbidden
    with pytest.raises(StudentError) as error:
        box.call("01", "exp_so3", [[0.0, 0.0, 0.5]], forbid=("coursekit.lie",))
    assert error.value.kind == "delegated" and "coursekit.lie.Exp" in error.value.message


def test_a_code_object_without_a_qualified_name_is_named_by_its_plain_name():
    """Python 3.10, the students' floor, has no ``co_qualname``: the tracer falls back to ``co_name``."""
    from types import SimpleNamespace

    from coursekit.watching import _qualname

    assert _qualname(SimpleNamespace(co_name="expm")) == "expm"
    method = _main("class Turn:\n    def about_z(self):\n        return 1")["Turn"].about_z
    assert _qualname(method.__code__) == ("Turn.about_z" if sys.version_info >= (3, 11) else "about_z")
