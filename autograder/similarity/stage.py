"""The similarity stage, end to end: read a class (and past terms), find, write.

``python -m autograder similarity CLASS [--out DIR] [--past DIR ...]`` calls
:func:`similarity_of_class` and :func:`write_findings`; ``grade`` does the same
after grading (``--no-similarity`` turns it off) and puts the section in the
class report. Everything runs on this machine.

Examples
--------
>>> findings = similarity_of_class(Path("class"), course, past=[Path("2025")])   # doctest: +SKIP
>>> paths = write_findings(findings, Path("out"))                          # doctest: +SKIP
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Callable

from autograder.lessons.course import Course
from autograder.lessons.reference import answer_sources
from autograder.similarity.answers import read_class, released_stubs
from autograder.similarity.findings import Findings, find_similar
from autograder.similarity.report import similar_answers_csv, similar_answers_html

CSV_NAME = "similar_answers.csv"
HTML_NAME = "similar_answers.html"


def similarity_of_class(
    path: str | Path,
    course: Course,
    past: tuple | list = (),
    jobs: int | None = None,
    summaries: dict | None = None,
) -> Findings:
    """The :class:`~autograder.similarity.findings.Findings` of the class under ``path``.

    ``summaries``: ``{student_id: answers}`` as the students' grading processes kept them
    (``StudentResult.answers``, :func:`~autograder.similarity.answers.summarize`); every other student is
    read in a forked process of its own, with limits. This process parses nothing of a student's.

    ``past``: folders of past terms' submissions (same layouts); their authors are named
    ``"<folder name>/<student>"``, and pairs within a past term are not compared. ``jobs``: processes
    that fingerprint the answers (default: the number of cores).
    """
    jobs = jobs or os.cpu_count() or 1
    current = read_class(path, course, jobs=jobs, summaries=summaries)
    earlier, unread = {}, dict(current.unread)
    for folder in past:
        answers = read_class(folder, course, prefix=f"{Path(folder).name}/", jobs=jobs)
        unread.update(answers.unread)
        for exercise, by_author in answers.by_exercise.items():
            earlier.setdefault(exercise, {}).update(by_author)
    return find_similar(
        current.by_exercise,
        answer_sources(course.solutions),
        released_stubs(course.released),
        earlier,
        unread,
        jobs=jobs,
    )


def write_findings(
    findings: Findings, out_dir: str | Path, write: Callable[[Path, str], None] | None = None
) -> tuple[Path, Path]:
    """Write ``similar_answers.csv`` and a stand-alone ``similar_answers.html`` into ``out_dir``.

    ``write(path, text)``: how to write a file (the batch's atomic writer); a plain write by default.
    """
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    write = write or (lambda p, text: Path(p).write_text(text, encoding="utf-8"))
    page = (
        '<!DOCTYPE html><html lang="en"><head><meta charset="utf-8"><title>Similar answers</title>'
        f"</head><body>{similar_answers_html(findings)}</body></html>\n"
    )
    write(out_dir / CSV_NAME, similar_answers_csv(findings))
    write(out_dir / HTML_NAME, page)
    return out_dir / CSV_NAME, out_dir / HTML_NAME
