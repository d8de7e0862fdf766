"""Run a lesson's public checks in this process on an answer cell's source (for the corpus tests).

The answer is executed the way the grader executes it: after the lesson's
setup cell and the reference answers of the other exercises, so a helper the
answer calls resolves as it would in the student's notebook.

Examples
--------
>>> ok, out = run_public_checks("rot_z", "def rot_z(a):\\n    return np.eye(3)\\n")  # doctest: +SKIP
>>> ok
False
"""

import contextlib
import io
from functools import lru_cache

from autograder.lessons.catalog import load_catalog
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import SOLUTIONS
from autograder.lessons.reference import lesson_namespace


@lru_cache(maxsize=None)
def _reference_namespace(lesson):
    return lesson_namespace(read_master(SOLUTIONS / load_catalog().lesson(lesson).filename), lesson)


def run_public_checks(exercise, source):
    """``(passed, printed)``: did every public check of ``exercise`` pass for the answer ``source``?"""
    import coursekit
    from coursekit.checking import CheckFailed

    namespace = dict(_reference_namespace(load_catalog().exercise(exercise).lesson))
    exec(compile(source, f"<answer {exercise}>", "exec"), namespace)
    out = io.StringIO()
    with contextlib.redirect_stdout(out):
        try:
            coursekit.check(exercise, namespace[exercise])
        except (CheckFailed, NotImplementedError):
            return False, out.getvalue()
    return "✗" not in out.getvalue(), out.getvalue()
