"""Run a lesson's public checks in this process on an answer cell's source (for the corpus tests).

The answer runs as the check cell would see it: after the lesson's setup cell
and the reference answers of the other exercises, in a namespace named
``__main__`` (so the checks see delegation to the library as they would in a
notebook). One definition, shared with the mutation tool:
:func:`autograder.mutants.inprocess.run_public_checks`.

Examples
--------
>>> ok, out = run_public_checks("rot_z", "def rot_z(a):\\n    return np.eye(3)\\n")  # doctest: +SKIP
>>> ok
False
"""

from autograder.mutants.inprocess import run_public_checks  # noqa: F401
