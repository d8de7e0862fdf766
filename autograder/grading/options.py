"""The knobs of a grading run (:class:`GradingOptions`), apart from the stages that read them.

Examples
--------
>>> GradingOptions(nbval=False, lessons=("01", "03")).lessons
('01', '03')
"""

from dataclasses import dataclass

from autograder.sandbox import launcher


@dataclass(frozen=True)
class GradingOptions:
    """Knobs of a grading run."""

    nbval: bool = True
    limits: launcher.Limits = launcher.Limits()
    lessons: tuple = ()  # lesson numbers to grade, e.g. ("01", "03"); empty means all
    notebook_points: float = 1.0  # per lesson, for "runs top to bottom and reproduces the reference"
