"""Exercises that were never attempted, and notebooks that could not be read: told once, not per check.

An untouched stub fails every hidden check with the same sentence (``rot_z is not written yet (it raises
NotImplementedError)``, from :mod:`autograder.sandbox.session`), and every check of a damaged notebook
fails with the notebook's reason. Reports say each of these once and keep them apart from real mistakes
(the class report's "most common failed checks").

Examples
--------
>>> unwritten_functions(exercise)                                                  # doctest: +SKIP
['rot_z']
"""

from __future__ import annotations

import re

from autograder.grading.results import ExerciseResult

NOT_WRITTEN = re.compile(r"(\S+) is not written yet \(it raises NotImplementedError\)")


def unwritten_functions(exercise: ExerciseResult) -> list[str]:
    """The functions (by name) whose stubs made every failed check of ``exercise`` fail; ``[]`` when any
    failure is a real one or nothing failed."""
    failed = [check for check in exercise.checks if not check.passed]
    found = [NOT_WRITTEN.search(check.reason or "") for check in failed]
    if not failed or not all(found):
        return []
    return list(dict.fromkeys(match.group(1) for match in found))
