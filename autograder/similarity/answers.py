"""Which answer each student wrote for each exercise, read the way the grader reads it.

The notebooks of a class folder are found and matched to lessons by
:mod:`autograder.grading.submissions`, and each exercise's answer cell is taken
by :func:`autograder.grading.extract.lesson_program` (by ``grade_id``, else by
the function it defines), so the similarity stage compares exactly what was
graded. A student whose folder cannot be read costs that student only: the
reason is kept in :attr:`ClassAnswers.unread`. An answer is compared on its
first :data:`MAX_ANSWER_CHARACTERS` characters, so a cell of megabytes costs
no more than a long answer.

Nothing of a student's is read, parsed or tokenised in the process that
compares the class: each student's grading process keeps its answers,
already tokenised, in its saved result (:func:`summarize`, bounded by
:data:`~autograder.grading.budget.ANSWERS_BYTES`), and a student without one
is read in a forked process of its own with limits of CPU time and memory
(:func:`read_class`). The comparing process only hashes the normalised code
(:func:`from_summary`).

Examples
--------
>>> answers = read_class(Path("class"), course)               # doctest: +SKIP
>>> answers.by_exercise["rot_z"]["ada"][:14]
'def rot_z(angle'
"""

from __future__ import annotations

import json
import os
import resource
import tempfile
import time
from dataclasses import dataclass, field
from functools import lru_cache
from pathlib import Path

from autograder.grading.budget import ANSWERS_BYTES, cut
from autograder.grading.extract import lesson_program
from autograder.grading.submissions import match_lessons, scan_submissions
from autograder.lessons import cells
from autograder.lessons.course import Course
from autograder.lessons.notebook_files import read_master, read_submission
from autograder.similarity.findings import MIN_LENGTH
from autograder.similarity.fingerprints import longest_coverage, normalised

MAX_ANSWER_CHARACTERS = 20_000  # a long answer is a few thousand
READER_CPU_SECONDS = 60  # CPU time of the forked process that reads one student's folder (reading is bounded)
READER_EXTRA_MEMORY = 1 << 30  # address space that process may add to what it was forked with


class Answer(str):
    """An answer's source that carries its ``normalised`` code (tokenised in the student's own process),
    so :func:`~autograder.similarity.fingerprints.fingerprint` only hashes it.

    >>> answer = Answer("def f(x):\\n    return x\\n")
    >>> answer.normalised = ("deff(V):returnV", [])
    >>> answer == "def f(x):\\n    return x\\n"
    True
    """

    normalised: tuple = ("", [])


def _entry(source, stub):
    code, offsets = "", []
    if source.strip() != stub.strip() and longest_coverage(source, stub) >= MIN_LENGTH:
        code, offsets = normalised(source, stub)
    return {"source": source, "normalised": code, "offsets": offsets}


def summarize(answers: dict[str, str], course: Course) -> dict[str, dict]:
    """``{exercise: {"source", "normalised", "offsets"}}``: a student's answers as the similarity stage
    compares them, tokenised here (in the student's own grading process), within
    :data:`~autograder.grading.budget.ANSWERS_BYTES` of ASCII JSON. Each answer has an equal share of it
    (about 29 KB for the 71 exercises of this course, ten times a long answer): an answer past its share is
    compared on its first part only, so padding one answer never hides another from the comparison.

    >>> summarize({"rot_z": "def rot_z(a):\\n    return a\\n"}, course)["rot_z"]["normalised"]  # doctest: +SKIP
    ''
    """
    stubs, summary = released_stubs(course.released), {}
    share = ANSWERS_BYTES // max(1, len(answers))
    for exercise in sorted(answers):
        stub, keep = stubs.get(exercise, ""), MAX_ANSWER_CHARACTERS
        entry = _entry(answers[exercise][:keep], stub)
        while keep and len(json.dumps(entry)) > share:
            keep //= 2
            entry = _entry(answers[exercise][:keep], stub)
        summary[cut(exercise, 200)] = entry
    return summary


def from_summary(summary: dict) -> dict[str, Answer]:
    """``{exercise: Answer}`` of a :func:`summarize` summary (answers omitted or malformed left out).

    >>> from_summary({"f": {"source": "x", "normalised": "", "offsets": []}})
    {'f': 'x'}
    """
    found = {}
    for exercise, entry in (summary or {}).items():
        try:
            answer = Answer(entry["source"])
            code, offsets = entry["normalised"], entry["offsets"]
            if not isinstance(code, str) or not all(isinstance(v, int) for v in offsets) or len(offsets) % 2:
                continue
            answer.normalised = (code, offsets)
        except (KeyError, TypeError):
            continue
        found[exercise] = answer
    return found


@dataclass
class ClassAnswers:
    """``by_exercise[exercise][author] = answer source``; ``unread[author] = why`` nothing was read."""

    by_exercise: dict = field(default_factory=dict)
    unread: dict = field(default_factory=dict)

    @property
    def authors(self) -> list[str]:
        return sorted({author for answers in self.by_exercise.values() for author in answers} | set(self.unread))


def student_answers(folder: Path, course: Course) -> dict[str, str]:
    """``{exercise: source}`` of one student's folder (lessons matched by content, cells by grade_id)."""
    catalog = course.catalog
    found, parsed = {}, {}

    def read(path):  # each notebook parsed once: matching lessons reads it, and so does taking its cells
        if path not in parsed:
            parsed[path] = read_submission(path, root=folder)
        return parsed[path]

    files = match_lessons(Path(folder), catalog, course.released, read=read)
    for lesson in catalog.graded_lessons:
        path = files.chosen.get(lesson.number)
        if path is None or path in files.unreadable:
            continue
        program = lesson_program(read(path), lesson)
        found.update((name, source[:MAX_ANSWER_CHARACTERS]) for name, source in program.cells)
    return found


def _summary_of_folder(folder, course):
    return summarize(student_answers(folder, course), course)


def _start_reader(folder, course):
    """Fork a process that reads one student's folder into a :func:`summarize` summary, with limits of CPU
    time, memory and output; return ``(pid, the file it writes)``."""
    out = tempfile.TemporaryFile()
    pid = os.fork()
    if pid:
        return pid, out
    code = 1
    try:
        with open("/proc/self/statm") as statm:
            size = int(statm.read().split()[0]) * os.sysconf("SC_PAGE_SIZE")
        resource.setrlimit(resource.RLIMIT_CPU, (READER_CPU_SECONDS, READER_CPU_SECONDS))
        resource.setrlimit(resource.RLIMIT_AS, (size + READER_EXTRA_MEMORY,) * 2)
        try:
            reply = [_summary_of_folder(folder, course), None]
        except Exception as error:
            reply = [None, cut(f"{type(error).__name__}: {error}", 300)]
        data = json.dumps(reply).encode()
        if len(data) > 2 * ANSWERS_BYTES:
            data = json.dumps([None, "its answers were larger than the similarity stage keeps"]).encode()
        out.write(data)
        out.flush()
        code = 0
    finally:
        os._exit(code)


def _finish_reader(pid, out, status):
    with out:
        if not os.WIFEXITED(status) or os.WEXITSTATUS(status):
            signal = os.WTERMSIG(status) if os.WIFSIGNALED(status) else None
            return None, f"reading it was stopped (limits of {READER_CPU_SECONDS} CPU s and memory; signal {signal})"
        out.seek(0)
        data = out.read(2 * ANSWERS_BYTES + 1)
    try:
        summary, why = json.loads(data)
    except ValueError:
        return None, "its reader's reply could not be read"
    return summary, why


def read_summaries(folders: list[Path], course: Course, jobs: int = 1) -> list[tuple[dict | None, str | None]]:
    """``[(summary, None) or (None, why)]`` for each student's folder, each read in a forked process of its
    own with limits (:func:`summarize`; ``jobs`` at a time), never in this one.

    >>> read_summaries([Path("class/ada")], course)               # doctest: +SKIP
    [({'rot_z': {...}}, None)]
    """
    results, running, waiting = [None] * len(folders), {}, list(enumerate(folders))
    while waiting or running:
        while waiting and len(running) < max(1, jobs):
            index, folder = waiting.pop(0)
            pid, out = _start_reader(folder, course)
            running[pid] = (index, out)
        for pid in list(running):
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                index, out = running.pop(pid)
                results[index] = _finish_reader(pid, out, status)
        if running:
            time.sleep(0.005)
    return results


def add_summary(answers: ClassAnswers, author: str, summary: dict | None, why: str | None = None) -> None:
    """Put one author's :func:`summarize` summary (or why there is none) into ``answers``."""
    if why is not None:
        answers.unread[author] = why
    for exercise, source in from_summary(summary).items():
        answers.by_exercise.setdefault(exercise, {})[author] = source


def read_class(
    path: str | Path, course: Course, prefix: str = "", jobs: int = 1, summaries: dict | None = None
) -> ClassAnswers:
    """Every student's answers under ``path`` (any layout :mod:`~autograder.grading.submissions` reads).

    ``prefix`` is put before each student id (``"past term/"`` for a past class), so authors from
    different folders never share a name. ``summaries``: ``{student_id: summary}`` kept by the students'
    grading processes (their saved results); a student without one is read in a forked process of its
    own with limits (:func:`read_summaries`, ``jobs`` at a time). Nothing of a student's is parsed here.
    """
    answers = ClassAnswers()
    students = scan_submissions(path).files
    summaries = summaries or {}
    unread = [(student_id, folder) for student_id, folder in students if summaries.get(student_id) is None]
    read = dict(zip((sid for sid, _ in unread), read_summaries([f for _, f in unread], course, jobs)))
    for student_id, _ in students:
        summary, why = read.get(student_id, (summaries.get(student_id), None))
        add_summary(answers, f"{prefix}{student_id}", summary, why)
    return answers


@lru_cache(maxsize=None)
def released_stubs(course_dir: Path) -> dict[str, str]:
    """``{exercise: the answer cell as released in course/}``: what every student started from."""
    stubs = {}
    for path in sorted(Path(course_dir).glob("[0-9][0-9]_*.ipynb")):
        for cell in read_master(path).cells:
            if cells.is_answer_cell(cell):
                stubs[cells.grade_id(cell)] = cells.source_text(cell)
    return stubs
