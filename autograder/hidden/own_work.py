"""Which library functions an exercise must not hand its work to: the course's own list.

The list lives in ``coursekit.contracts`` (it ships to students, so the check
cells can say the same as the grader); the grader sends each exercise's entries
with every call of it, the sandbox watches the call
(:mod:`coursekit.watching`), and a call that used one of them directly from the
student's code earns the exercise no points, with the reason.
"""

import sys

from autograder.lessons.paths import SOLUTIONS

if str(SOLUTIONS) not in sys.path:
    sys.path.insert(0, str(SOLUTIONS))  # coursekit, as the hidden suite finds it

from coursekit.contracts import CHANGED_HINT, DELEGATED_HINT, FORBIDDEN, forbidden_for  # noqa: F401  (for the tests)
