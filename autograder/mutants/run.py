"""Grade every mutant with the hidden suite and the public checks, on a few processes; print the table.

``python -m autograder mutants`` (see :func:`main`). Each mutant is put in
place of its exercise's reference answer and graded in this process's forks
(:mod:`autograder.mutants.inprocess`): killed by the hidden suite when its
exercise loses a point, killed by the public checks when the check cell prints
a ✗. Mutants listed in :mod:`autograder.mutants.equivalent` are counted apart;
every other mutant that keeps full hidden marks is a survivor, and is printed.

Targets (docs in the README): the hidden suite kills at least
:data:`HIDDEN_TARGET` of the non-equivalent mutants of every exercise, and the
public checks at least :data:`PUBLIC_TARGET` of what the hidden suite kills.
"""

from __future__ import annotations

import functools
import multiprocessing
import os
import time
import warnings
from dataclasses import dataclass, field
from typing import Callable

from autograder.mutants.equivalent import EQUIVALENT
from autograder.lessons.course import Course
from autograder.mutants.generate import Mutant, all_mutants

HIDDEN_TARGET = 0.98
PUBLIC_TARGET = 0.90


@dataclass
class Outcome:
    """What both suites did to one mutant."""

    key: str
    exercise: str
    family: str
    description: str
    hidden_killed: bool
    public_killed: bool
    points: float = 0.0
    max_points: float = 0.0
    hidden_hints: list = field(default_factory=list)  # (reason, hint) of the failed hidden checks
    public_lines: list = field(default_factory=list)  # the ✗ and hint lines the check cell printed
    elsewhere: list = field(default_factory=list)  # other exercises that lost points (should be none)
    error: str = ""  # the grading itself failed (counted as a survivor, and said)

    @property
    def equivalent(self) -> bool:
        return self.key in EQUIVALENT


def grade_mutant(course: Course, mutant: Mutant) -> Outcome:
    """The :class:`Outcome` of one mutant (both suites share one in-process sandbox)."""
    from autograder.mutants.inprocess import InProcessSandbox, grade_hidden, lesson_programs, run_public_checks

    try:
        sandbox = InProcessSandbox(lesson_programs(course, mutant.lesson, {mutant.exercise: mutant.source}))
        hidden = grade_hidden(course, mutant.exercise, mutant.source, sandbox)
        public_passed, printed = run_public_checks(course, mutant.exercise, mutant.source, sandbox)
    except Exception as error:  # noqa: BLE001 (one mutant's trouble is reported, the run goes on)
        return Outcome(
            mutant.key,
            mutant.exercise,
            mutant.family,
            mutant.description,
            False,
            False,
            error=f"{type(error).__name__}: {error}",
        )
    lines = [line.strip() for line in printed.splitlines() if line.strip().startswith(("✗", "hint:"))]
    return Outcome(
        mutant.key,
        mutant.exercise,
        mutant.family,
        mutant.description,
        hidden.killed,
        not public_passed,
        hidden.points,
        hidden.max_points,
        [(reason, hint) for _, reason, hint in hidden.failed],
        lines,
        hidden.elsewhere,
    )


def _preload(course):
    """Everything the forks share: the suite collected, the reference's calls recorded, the checks imported."""
    from autograder.grading.suite import hidden_tests, single_threaded_blas, transcripts_for
    from autograder.mutants.inprocess import _worker_module

    warnings.simplefilter("ignore")  # a mutant's overflow or 0/0 is its own business (the sandbox keeps it too)
    single_threaded_blas()
    course.use_support_package()
    hidden_tests(course)
    transcripts_for(course.reference, course)
    _worker_module()
    import coursekit.checks  # noqa: F401  (importing registers every lesson's checks)


def grade_all(
    course: Course, mutants: list[Mutant], jobs: int | None = None, progress: Callable[[int, int], None] | None = None
) -> list[Outcome]:
    """Outcomes of ``mutants``, in their order; ``jobs`` forked processes (default: the cores, at most 2)."""
    _preload(course)
    jobs = jobs or min(2, os.cpu_count() or 1)
    if jobs <= 1:
        outcomes = []
        for mutant in mutants:
            outcomes.append(grade_mutant(course, mutant))
            if progress:
                progress(len(outcomes), len(mutants))
        return outcomes
    with multiprocessing.get_context("fork").Pool(jobs) as pool:
        outcomes = []
        for outcome in pool.imap(functools.partial(grade_mutant, course), mutants, chunksize=4):
            outcomes.append(outcome)
            if progress:
                progress(len(outcomes), len(mutants))
    return outcomes


@dataclass
class Row:
    exercise: str
    mutants: int = 0
    hidden: int = 0
    public: int = 0  # killed by both (the public checks' share of what the hidden suite kills)
    public_only: int = 0  # killed by the public checks, survived the hidden suite
    equivalent: int = 0
    survivors: list = field(default_factory=list)

    @property
    def hidden_rate(self) -> float:
        candidates = self.mutants - self.equivalent
        return self.hidden / candidates if candidates else 1.0

    @property
    def public_rate(self) -> float:
        return self.public / self.hidden if self.hidden else 1.0

    @property
    def meets(self) -> bool:
        return self.hidden_rate >= HIDDEN_TARGET and self.public_rate >= PUBLIC_TARGET


def table(outcomes: list[Outcome], exercises: list[str]) -> tuple[list[Row], Row]:
    """One :class:`Row` per exercise (in ``exercises``' order) and a total row."""
    rows = {name: Row(name) for name in exercises}
    for outcome in outcomes:
        row = rows[outcome.exercise]
        row.mutants += 1
        if outcome.equivalent:
            row.equivalent += 1
            continue
        if outcome.hidden_killed:
            row.hidden += 1
            row.public += outcome.public_killed
        else:
            row.public_only += outcome.public_killed
            row.survivors.append(outcome)
    total = Row("all")
    for row in rows.values():
        for name in ("mutants", "hidden", "public", "public_only", "equivalent"):
            setattr(total, name, getattr(total, name) + getattr(row, name))
        total.survivors += row.survivors
    return list(rows.values()), total


def format_table(rows: list[Row], total: Row, markdown: bool = False) -> str:
    """The table as text (or as a Markdown table for the README)."""
    header = [
        "exercise",
        "mutants",
        "equivalent",
        "killed by hidden",
        "killed by public",
        "survivors",
        "hidden kill rate",
        "public / hidden",
        "targets",
    ]
    lines = []
    for row in rows + [total]:
        cells = [
            row.exercise,
            str(row.mutants),
            str(row.equivalent),
            str(row.hidden),
            str(row.public) + (f" (+{row.public_only})" if row.public_only else ""),
            str(len(row.survivors)),
            f"{100 * row.hidden_rate:.1f}%",
            f"{100 * row.public_rate:.1f}%",
            "met" if row.meets else "MISSED",
        ]
        lines.append(cells)
    if markdown:
        out = ["| " + " | ".join(header) + " |", "|" + " --- |" * len(header)]
        out += ["| " + " | ".join(cells) + " |" for cells in lines]
        return "\n".join(out)
    widths = [max(len(header[i]), *(len(cells[i]) for cells in lines)) for i in range(len(header))]
    out = ["  ".join(h.ljust(w) for h, w in zip(header, widths))]
    out += ["  ".join(c.ljust(w) for c, w in zip(cells, widths)) for cells in lines]
    return "\n".join(out)


def stale_equivalents(mutants: list[Mutant]) -> list[str]:
    """Keys in :data:`EQUIVALENT` that no generated mutant has (the reference changed: review them)."""
    keys = {m.key for m in mutants}
    return sorted(key for key in EQUIVALENT if key not in keys)


def main(
    course: Course,
    exercises: list[str] | None = None,
    lessons: list[str] | None = None,
    jobs: int | None = None,
    markdown: bool = False,
    show_survivors: bool = True,
    out: Callable[[str], None] = print,
    save: str | None = None,
) -> int:
    """Generate, grade and report; return 0 when every exercise meets both targets, else 1.

    ``save``: a path to write every outcome to, as JSON (for reading survivors and hints at leisure).
    """
    started = time.monotonic()
    mutants = all_mutants(course, exercises, lessons)
    names = [
        e.name
        for e in course.catalog.exercises
        if (not exercises or e.name in exercises) and (not lessons or e.lesson in lessons)
    ]
    out(
        f"{len(mutants)} mutants of {len(names)} exercises, graded by the hidden suite and the public checks "
        f"({jobs or min(2, os.cpu_count() or 1)} processes)"
    )
    outcomes = grade_all(course, mutants, jobs)
    if save:
        import dataclasses
        import json
        from pathlib import Path

        Path(save).write_text(
            json.dumps([dict(dataclasses.asdict(o), source=m.source) for o, m in zip(outcomes, mutants)], indent=1),
            encoding="utf-8",
        )
    rows, total = table(outcomes, names)
    out(format_table(rows, total, markdown))
    if show_survivors and total.survivors:
        out("\nSurvivors (non-equivalent mutants that keep full hidden marks):")
        for outcome in total.survivors:
            public = "killed by public" if outcome.public_killed else "passes public"
            out(
                f"  {outcome.key}  [{outcome.family}] {outcome.description}  ({public})"
                + (f"  grading failed: {outcome.error}" if outcome.error else "")
            )
    wrongly = [o for o in outcomes if o.equivalent and (o.hidden_killed or o.public_killed)]
    if wrongly:
        out("\nListed as equivalent (correct answers) but losing points or failing a public check:")
        for outcome in wrongly:
            out(
                f"  {outcome.key}  [{outcome.family}] {outcome.description}  "
                f"(hidden {outcome.points:g}/{outcome.max_points:g}, public {'✗' if outcome.public_killed else '✓'})"
            )
    spilled = [o for o in outcomes if o.elsewhere]
    for outcome in spilled:
        out(f"  {outcome.key} also cost points on {', '.join(outcome.elsewhere)}")
    if not exercises and not lessons:
        for key in stale_equivalents(mutants):
            out(f"  equivalent.py lists {key}, which no operator makes any more: review it")
    out(f"\n{time.monotonic() - started:.0f} s")
    return 0 if all(row.meets for row in rows) and not wrongly else 1
