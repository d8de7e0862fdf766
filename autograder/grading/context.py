"""What grades a submission besides the submission itself: :class:`GradingContext`.

Built once per run (the CLI's ``grade`` and ``canary``, a Gradescope container) and passed down to every
student's grading, so that no stage looks up which course it grades or with which settings.

Examples
--------
>>> context = GradingContext(course, GradingOptions(nbval=False))   # doctest: +SKIP
>>> result = grade_student("ada", Path("class/ada"), context)         # doctest: +SKIP
"""

from __future__ import annotations

from dataclasses import dataclass

from autograder.grading.options import GradingOptions
from autograder.lessons.course import Course
from autograder.sandbox import launcher


@dataclass(frozen=True)
class GradingContext:
    """The course graded and the run's options; plain data, so it pickles to a forked grader or a Dask worker.

    Where a student's sandboxes come from is the grading process's own: a warm slot
    (:class:`~autograder.sandbox.warm.WarmSlot`) handed to it by the runner, or cold starts, so it is given
    beside the context (``slot=``), not in it. The late policy is applied after grading, by ``batch``.

    Attributes
    ----------
    course : Course
        The course folder's parts (:class:`~autograder.lessons.course.Course`).
    options : GradingOptions
        Which lessons, the notebook stage or not, and the sandbox's resource limits.
    """

    course: Course
    options: GradingOptions = GradingOptions()

    @property
    def limits(self) -> launcher.Limits:
        """The resource limits of every sandbox of this run."""
        return self.options.limits
