"""What the exercises of a course ask for: counts, points and minutes by kind, per lesson and in all.

Each exercise's kind and estimated minutes come from its answer cell's ``exercise`` metadata
(:mod:`autograder.lessons.catalog`; COURSE_SPEC.md, "Exercise kinds"). ``python -m autograder
course-stats`` prints :func:`stats_table`; ``--markdown`` the same table in Markdown; ``--catalog``
the page ``docs/EXERCISES.md`` (:func:`catalog_page`), which is generated, never edited by hand
(``tests/test_answers_off_page.py`` checks that it is current).

The targets of issue 42 (:data:`SHARE_TARGET`, :data:`THINKING_TARGET`): from lesson
:data:`FIRST_TARGETED_LESSON` on, at least a third of every lesson's exercise points are derive,
design or diagnose, and the course has at least 15 such exercises.

Examples
--------
>>> from pathlib import Path
>>> from autograder.lessons.catalog import load_catalog
>>> print(stats_table(load_catalog(Path("solutions"))))  # doctest: +SKIP
"""

from __future__ import annotations

from dataclasses import dataclass
from fractions import Fraction

from autograder.lessons.catalog import KINDS, THINKING_KINDS, Catalog, Exercise, Lesson

SHARE_TARGET = Fraction(1, 3)  # of a lesson's exercise points, from FIRST_TARGETED_LESSON on
FIRST_TARGETED_LESSON = "03"
THINKING_TARGET = 15  # derive, design or diagnose exercises in the whole course
UNCLASSIFIED = "unclassified"


@dataclass(frozen=True)
class KindStats:
    """The exercises of one lesson (or of the course) in figures."""

    label: str
    exercises: tuple[Exercise, ...]

    def count(self, kind: str) -> int:
        return sum(1 for e in self.exercises if (e.kind or UNCLASSIFIED) == kind)

    def points(self, kind: str | None = None) -> float:
        return sum(e.points for e in self.exercises if kind is None or (e.kind or UNCLASSIFIED) == kind)

    @property
    def thinking_count(self) -> int:
        return sum(1 for e in self.exercises if e.kind in THINKING_KINDS)

    @property
    def thinking_points(self) -> float:
        return sum(e.points for e in self.exercises if e.kind in THINKING_KINDS)

    @property
    def thinking_share(self) -> float:
        """The share of the points that are derive, design or diagnose (0 without exercises)."""
        total = self.points()
        return self.thinking_points / total if total else 0.0

    @property
    def minutes(self) -> int:
        return sum(e.minutes for e in self.exercises)


def lesson_stats(lesson: Lesson) -> KindStats:
    return KindStats(label=lesson.number, exercises=lesson.exercises)


def course_totals(catalog: Catalog) -> KindStats:
    return KindStats(label="all", exercises=catalog.exercises)


def _kinds_present(catalog: Catalog) -> tuple[str, ...]:
    unclassified = any(not e.kind for e in catalog.exercises)
    return KINDS + ((UNCLASSIFIED,) if unclassified else ())


def kinds_summary(lesson: Lesson) -> str:
    """One phrase for the README's course table: ``"9 (12 points): 7 transcribe, 2 assemble"``.

    Kinds with no exercise are left out; the kinds read in the order of :data:`KINDS`.
    """
    stats = lesson_stats(lesson)
    parts = [f"{stats.count(kind)} {kind}" for kind in KINDS + (UNCLASSIFIED,) if stats.count(kind)]
    return f"{len(lesson.exercises)} ({stats.points():g} points): " + ", ".join(parts)


def _row(stats: KindStats, kinds: tuple[str, ...]) -> list[str]:
    cells = [stats.label, str(len(stats.exercises)), f"{stats.points():g}"]
    cells += [f"{stats.count(kind)} / {stats.points(kind):g}" if stats.count(kind) else "—" for kind in kinds]
    cells += [f"{stats.thinking_count} / {stats.thinking_points:g}", f"{stats.thinking_share:.0%}", str(stats.minutes)]
    return cells


def _header(kinds: tuple[str, ...]) -> list[str]:
    return ["lesson", "exercises", "points", *kinds, "derive+design+diagnose", "share of points", "minutes"]


def _rows(catalog: Catalog) -> tuple[list[str], list[list[str]]]:
    kinds = _kinds_present(catalog)
    rows = [_row(lesson_stats(lesson), kinds) for lesson in catalog.graded_lessons]
    rows.append(_row(course_totals(catalog), kinds))
    return _header(kinds), rows


def meets_share(stats: KindStats) -> bool:
    """At least :data:`SHARE_TARGET` of the points are derive, design or diagnose (exactly, no rounding)."""
    return Fraction(stats.thinking_points) >= SHARE_TARGET * Fraction(stats.points())


def target_gaps(catalog: Catalog) -> list[str]:
    """What stands between the course and the targets of issue 42, one sentence each (empty when met)."""
    gaps = []
    for lesson in catalog.graded_lessons:
        stats = lesson_stats(lesson)
        needed = float(SHARE_TARGET) * stats.points() - stats.thinking_points
        if lesson.number >= FIRST_TARGETED_LESSON and not meets_share(stats):
            gaps.append(
                f"lesson {lesson.number}: {stats.thinking_share:.0%} of its points are derive/design/diagnose "
                f"(target ≥ 1/3: {needed:.3g} more point(s))"
            )
    total = course_totals(catalog).thinking_count
    if total < THINKING_TARGET:
        gaps.append(f"the course has {total} derive/design/diagnose exercises (target ≥ {THINKING_TARGET})")
    return gaps


def _targets_text(catalog: Catalog) -> list[str]:
    gaps = target_gaps(catalog)
    head = (
        f"Targets (issue 42): from lesson {FIRST_TARGETED_LESSON} on, ≥ 1/3 of each lesson's exercise points "
        f"derive/design/diagnose; ≥ {THINKING_TARGET} such exercises in all."
    )
    return [head, *([f"- {gap}" for gap in gaps] if gaps else ["- all met."])]


def stats_table(catalog: Catalog) -> str:
    """Per lesson and in all: exercises, points, each kind as ``count / points``, the derive/design/diagnose
    share of the points and the estimated minutes; then the targets and what is missing."""
    header, rows = _rows(catalog)
    widths = [max(len(row[i]) for row in [header, *rows]) for i in range(len(header))]
    lines = ["  ".join(cell.rjust(width) for cell, width in zip(row, widths)) for row in [header, *rows]]
    lines.insert(1, "  ".join("-" * width for width in widths))
    return "\n".join(lines + ["", *_targets_text(catalog)])


def _markdown_table(header: list[str], rows: list[list[str]]) -> list[str]:
    escaped = [[cell.replace("|", "\\|") for cell in row] for row in [header, *rows]]
    lines = ["| " + " | ".join(escaped[0]) + " |", "| " + " | ".join("---" for _ in header) + " |"]
    return lines + ["| " + " | ".join(row) + " |" for row in escaped[1:]]


def stats_markdown(catalog: Catalog) -> str:
    """:func:`stats_table` in Markdown (each kind's cell is ``count / points``)."""
    header, rows = _rows(catalog)
    return "\n".join(_markdown_table(header, rows) + ["", *_targets_text(catalog)])


def catalog_page(catalog: Catalog) -> str:
    """``docs/EXERCISES.md``: every exercise with its lesson, kind, points, minutes and meaning, and the
    figures by kind."""
    lines = [
        "# The exercises",
        "",
        "<!-- Generated by `python -m autograder course-stats --catalog > docs/EXERCISES.md`: do not edit. -->",
        "",
        "Every graded exercise of the course, read from the masters (`solutions/NN_*.ipynb`): its kind and",
        "estimated minutes are the answer cell's `exercise` metadata, its meaning the first line of its",
        'docstring. The kinds (COURSE_SPEC.md, "Exercise kinds"): *transcribe*, the formula or algorithm is',
        "on the page; *assemble*, the page lists the ingredients; *derive*, the page gives the definition and",
        "the tools, never the result; *design*, a measurable objective and no recipe; *diagnose*, code, data",
        "or a convention to examine, with a checkable answer.",
        "",
        "## By lesson",
        "",
        "Each kind's cell reads `exercises / points`.",
        "",
        stats_markdown(catalog),
        "",
        "## Every exercise",
        "",
    ]
    header = ["exercise", "lesson", "kind", "points", "minutes", "meaning"]
    rows = [
        [f"`{e.name}`", e.lesson, e.kind or UNCLASSIFIED, f"{e.points:g}", str(e.minutes or "—"), e.meaning]
        for e in catalog.exercises
    ]
    return "\n".join(lines + _markdown_table(header, rows)) + "\n"
