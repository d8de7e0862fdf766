"""What grading one student produces, as plain data that round-trips through JSON.

Statuses, used the same way in the gradebook, the feedback page and the
class report:

- ``graded``: every notebook was found, read and graded;
- ``graded with problems``: graded, but something is worth a look (a notebook
  missing or unreadable, a re-created answer cell, a crash); each problem is
  listed;
- ``could not grade``: nothing could be graded for an infrastructure reason
  (the reason is given); this is not a zero;
- ``missing``: no submission at all.
"""

from __future__ import annotations

import json
from dataclasses import asdict, dataclass, field

GRADED = "graded"
GRADED_WITH_PROBLEMS = "graded with problems"
COULD_NOT_GRADE = "could not grade"
MISSING = "missing"


@dataclass
class CheckResult:
    """One hidden test item."""

    exercise: str
    description: str
    weight: float
    passed: bool
    reason: str = ""
    hint: str = ""
    printed: str = ""


@dataclass
class ExerciseResult:
    name: str
    lesson: str
    max_points: float
    points: float = 0.0
    checks: list = field(default_factory=list)  # CheckResult
    notes: list = field(default_factory=list)  # e.g. the answer cell failed to run


@dataclass
class NotebookRun:
    """The nbval stage of one lesson: did the notebook run and reproduce the reference?"""

    status: str  # "passed", "failed", "skipped"
    max_points: float = 0.0
    points: float = 0.0
    failures: list = field(default_factory=list)  # one line per failing cell


@dataclass
class LessonResult:
    number: str
    title: str
    notebook: str
    status: str  # "graded", "missing", "unreadable"
    reason: str = ""
    exercises: list = field(default_factory=list)  # ExerciseResult
    run: NotebookRun = None
    submitted_at: str = ""  # ISO 8601, UTC: when this notebook was handed in (autograder.reports.lateness)
    late_penalty: float = 0.0  # fraction of the points taken for lateness, 0..1
    late_note: str = ""  # one sentence: when it was due, how late, how much
    submitted_from: str = ""  # where submitted_at came from: "timestamp.txt" or "file time" (its mtime)
    due: str = ""  # the due date as people read it, in the course's timezone ("2026-12-01 23:59 CET")

    @property
    def raw_points(self) -> float:
        """Points earned, before any late penalty."""
        return sum(e.points for e in self.exercises) + (self.run.points if self.run else 0.0)

    @property
    def points(self) -> float:
        """Points that count: the raw points less the late penalty."""
        return round(self.raw_points * (1.0 - self.late_penalty), 2)

    @property
    def max_points(self) -> float:
        return sum(e.max_points for e in self.exercises) + (self.run.max_points if self.run else 0.0)


@dataclass
class StudentResult:
    student_id: str
    status: str
    reason: str = ""
    submission_hash: str = ""
    lessons: list = field(default_factory=list)  # LessonResult
    problems: list = field(default_factory=list)
    seconds: float = 0.0
    isolation: str = ""  # "namespaces" or "limits": how the student's code was isolated (sandbox.launcher)
    skipped: list = field(default_factory=list)  # "path: why" for what the grader saw in the folder and did not use
    answers: dict | None = None  # exercise -> the answer as the similarity stage compares it (None: not made)

    @property
    def score(self) -> float:
        """The score that counts (late penalties applied)."""
        return round(sum(lesson.points for lesson in self.lessons), 2)

    @property
    def raw_score(self) -> float:
        """The score before late penalties."""
        return round(sum(lesson.raw_points for lesson in self.lessons), 2)

    @property
    def submitted_at(self) -> str:
        """When the newest of the student's notebooks was handed in (ISO 8601, UTC), or ""."""
        return max((lesson.submitted_at for lesson in self.lessons), default="")

    @property
    def max_score(self) -> float:
        return round(sum(lesson.max_points for lesson in self.lessons), 2)

    @property
    def exercises(self) -> list[ExerciseResult]:
        return [e for lesson in self.lessons for e in lesson.exercises]

    def to_json(self) -> str:
        data = asdict(self)
        data["score"], data["max_score"], data["raw_score"] = self.score, self.max_score, self.raw_score
        return json.dumps(data, indent=1, sort_keys=True, ensure_ascii=False)

    @classmethod
    def from_json(cls, text: str) -> StudentResult:
        data = json.loads(text)
        for derived in ("score", "max_score", "raw_score"):
            data.pop(derived, None)
        lessons = []
        for lesson in data.pop("lessons", []):
            exercises = []
            for exercise in lesson.pop("exercises", []):
                checks = [CheckResult(**c) for c in exercise.pop("checks", [])]
                exercises.append(ExerciseResult(checks=checks, **exercise))
            run = lesson.pop("run", None)
            lessons.append(LessonResult(exercises=exercises, run=NotebookRun(**run) if run else None, **lesson))
        return cls(lessons=lessons, **data)
