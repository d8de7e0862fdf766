"""Grade a whole class: a pool of forked graders, one student per process.

The parent imports everything once (numpy, scipy, pytest, the hidden suite,
the reference solutions) and then forks a fresh grader per student
(:mod:`autograder.sandbox.forking`), so starting a student costs a fork, not a Python
start-up, and no state survives from one student to the next. A grader that
dies is reported as "could not grade" with the reason; the batch goes on.
Each concurrent grader has a warm sandbox slot (:mod:`autograder.sandbox.warm`)
whose zygote forks the student's worker, so the sandbox side costs a fork too.

Before any student, the canary (:mod:`autograder.grading.canary`) grades the
reference solutions through the same pipeline; if they do not get full marks
the batch stops and nothing is written.

Every per-student step is contained: whatever a student's folder holds,
and whatever goes wrong while grading, saving or recording that student
(any exception; a result that cannot be saved is kept in memory for this
run's gradebook), costs that student alone, with the reason, and the
gradebook and the class report are always written. Entries of the
submissions folder that are not students (hidden, links, stray files) are
listed with why in ``OUT/skipped.json``, the run's output and the report.

Each student's result is written atomically to ``OUT/students/<id>.json``
(a bounded, collision-free file name: :func:`~autograder.lessons.untrusted_text.safe_name`)
as soon as it is ready, with the content hash of the submission and the
grader's fingerprint (:mod:`autograder.grading.fingerprint`: its code, the masters,
the hidden suite, coursekit, the options, the isolation mode, the library
versions). A re-run skips students whose submission and fingerprint did not
change (``force`` re-grades) and records why it re-graded the others, so an
interrupted run loses nothing already graded.
"""

from __future__ import annotations

import functools
import hashlib
import json
import os
import resource
import signal
import sys
import time
import traceback
from contextlib import nullcontext
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Callable, NamedTuple, Protocol

from autograder.batch.progress import Progress
from autograder.grading import submissions
from autograder.grading.budget import GRADESCOPE_BYTES, PAGE_BYTES, RESULT_BYTES, fit_result, read_capped
from autograder.grading.canary import canary_cached, describe_canary, ensure_reference_passes
from autograder.grading.fingerprint import fingerprint, fingerprint_parts, what_changed
from autograder.grading.context import GradingContext
from autograder.grading.pipeline import GradingOptions, grade_student
from autograder.grading.results import COULD_NOT_GRADE, MISSING, StudentResult
from autograder.grading.nbval_stage import record_notebook_calls
from autograder.grading.recording_lock import recording_turn
from autograder.grading.suite import learn_reference_in_sandbox, preload_hidden_suite
from autograder.lessons.course import Course
from autograder.lessons.untrusted_text import one_line, safe_name
from autograder.reports import feedback
from autograder.reports.gradebook import gradebook_csv
from autograder.reports.gradescope_results import results_json
from autograder.reports.lateness import CourseConfig
from autograder.reports.lateness import apply_late_policy
from autograder.reports.plain_page import plain_page
from autograder.sandbox import cleanup, launcher, process_tree, warm
from autograder.sandbox.forking import fork_each
from autograder.similarity.answers import released_stubs, summarize

STUDENT_TIMEOUT = 900


class GradingTask(NamedTuple):
    """One student to grade, as a runner (local forks, a Dask cluster) hands it to :func:`grade_task`.

    Plain data (paths as text), so it pickles to a Dask worker.
    """

    student_id: str
    folder: str  # the student's submission folder
    context: GradingContext  # the course and the run's options (paths only: a Dask worker rebuilds the rest)
    out_root: str  # the run's output folder (:class:`Outputs`)
    stamp: "Stamp"
    config: object  # the course's settings (a CourseConfig) or None
    layout: str = submissions.FOLDERS  # how the class is read (submissions.detect_layout): dates the hand-ins


class Runner(Protocol):
    """How the students' tasks run: forks of this process (:func:`~autograder.sandbox.forking.fork_each`,
    the default) or a Dask cluster (:func:`autograder.integrations.cluster.runner_for`).

    A runner calls ``grade(task, slot)`` for every task, in a process of its own (``slot``: that
    process's :class:`~autograder.sandbox.warm.WarmSlot`, or None), and ``on_done(task, problem)`` in the
    caller's process as each ends (``problem``: None, or a sentence on how the grading process died).
    """

    def __call__(
        self,
        grade: Callable[[GradingTask, warm.WarmSlot | None], None],
        tasks: list[GradingTask],
        jobs: int,
        on_done: Callable[[GradingTask, str | None], None],
        deadline_seconds: float | None = None,
    ) -> None: ...


PRIVATE_FOLDER, SHARED_READ = 0o700, 0o055  # output folders; what --share-output adds (group and others read)
OUTPUT_FOLDERS = ("students", "feedback", "results")  # the grader's folders in the output folder
OUTPUT_SUFFIXES = (".csv", ".html", ".json")  # and its files there (grades.csv, report.html, skipped.json, ...)


def _output_folder(folder):
    """Make ``folder`` (and missing parents) as readable as the folder above it: private (0700) under a private
    output folder, group and others read under a shared one (:func:`set_output_sharing`)."""
    folder = Path(folder)
    missing = []
    while not folder.exists():
        missing.append(folder)
        folder = folder.parent
    for made in reversed(missing):
        made.mkdir(exist_ok=True)
        os.chmod(made, PRIVATE_FOLDER | (SHARED_READ if os.stat(made.parent).st_mode & 0o044 else 0))


def set_output_sharing(root: str | Path, share: bool = False) -> None:
    """Make the output folder ``root`` and everything the grader wrote in it readable by its owner only
    (folders 0700, files 0600), or, with ``share`` (``grade --share-output``), by group and others too
    (0755, 0644). Files written later follow their folder (:func:`write_atomically`).

    >>> set_output_sharing("results")                                   # doctest: +SKIP
    """
    root = Path(root)
    root.mkdir(parents=True, exist_ok=True)
    extra = SHARED_READ if share else 0
    # the top may be crossed, never listed (0711): a class folder the instructor keeps inside it (the sample
    # class) stays readable by the sandbox's user in limits mode; what the grader writes is 0700/0600 below
    os.chmod(root, PRIVATE_FOLDER | extra | 0o011)
    for entry in _grader_outputs(root):
        folder = entry.is_dir(follow_symlinks=False)
        os.chmod(entry.path, PRIVATE_FOLDER | extra if folder else 0o600 | (extra & 0o044))


def _grader_outputs(root):
    """The entries of ``root`` the grader writes (its folders' files and its own files at the top), never links."""
    with os.scandir(root) as top:
        for entry in top:
            if entry.is_symlink():
                continue
            if entry.is_dir(follow_symlinks=False) and entry.name in OUTPUT_FOLDERS:
                yield entry
                with os.scandir(entry.path) as inside:
                    yield from (e for e in inside if e.is_file(follow_symlinks=False))
            elif entry.is_file(follow_symlinks=False) and entry.name.endswith(OUTPUT_SUFFIXES):
                yield entry


def write_atomically(path: str | Path, text: str) -> None:
    """Write ``text`` to ``path`` through a temporary file and a rename; text that UTF-8 cannot encode
    (lone surrogates) is written as backslash escapes rather than failing. The file is readable by its owner
    only (0600) unless its folder is shared (:func:`set_output_sharing`), then by group and others too."""
    path = Path(path)
    _output_folder(path.parent)
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    flags = os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW | os.O_CLOEXEC
    descriptor = os.open(tmp, flags, 0o600)
    os.fchmod(descriptor, 0o600 | (os.stat(path.parent).st_mode & 0o044))
    with open(descriptor, "w", encoding="utf-8", errors="backslashreplace") as handle:
        handle.write(text)
        handle.flush()
        os.fsync(handle.fileno())
    os.replace(tmp, path)


@dataclass
class Outputs:
    """Where a run writes; all under one directory."""

    root: Path

    def student_json(self, student_id: str) -> Path:
        return self.root / "students" / f"{safe_name(student_id)}.json"

    def feedback_html(self, student_id: str) -> Path:
        return self.root / "feedback" / f"{safe_name(student_id)}.html"

    def gradescope_json(self, student_id: str) -> Path:
        return self.root / "results" / f"{safe_name(student_id)}.json"

    def student_files(self, student_id: str) -> list[tuple[str, Path]]:
        """``[(kind, path)]``: the files a graded student leaves, in the order they are written (the saved
        result last: its presence means the others are complete)."""
        return [
            ("feedback", self.feedback_html(student_id)),
            ("gradescope", self.gradescope_json(student_id)),
            ("student", self.student_json(student_id)),
        ]

    @property
    def gradebook(self) -> Path:
        return self.root / "grades.csv"

    @property
    def skipped(self) -> Path:
        """Entries of the submissions folder that are not students, with why (JSON)."""
        return self.root / "skipped.json"

    @property
    def report(self) -> Path:
        return self.root / "report.html"


@dataclass(frozen=True)
class Stamp:
    """What a saved result says about how it was graded: the grader's fingerprint and why it was graded."""

    fingerprint: str
    parts: dict
    because: str = ""


@dataclass
class Saved:
    stamp: Stamp
    result: StudentResult


def load_saved(outputs: Outputs, student_id: str) -> Saved | None:
    """The :class:`Saved` result of a student, or None."""
    path = outputs.student_json(student_id)
    try:
        data = json.loads(read_capped(path))  # at most RESULT_BYTES: a bounded summary per student
        stamp = Stamp(data["fingerprint"], data.get("fingerprint_parts") or {}, data.get("graded_because", ""))
        return Saved(stamp, StudentResult.from_json(json.dumps(data["result"])))
    except (OSError, ValueError, KeyError, TypeError):
        return None


def regrade_reason(saved: Saved | None, stamp: Stamp, submission_hash: str, force: bool = False) -> str | None:
    """Why a student must be graded now, or ``None`` when the saved result can be reused."""
    if force:
        return "re-graded on request (--force or --student)"
    if saved is None:
        return "first grading"
    if saved.result.status == COULD_NOT_GRADE:
        return "the last attempt could not grade"
    if saved.result.submission_hash != submission_hash:
        return "the submission changed"
    if saved.stamp.fingerprint != stamp.fingerprint:
        changed = what_changed(saved.stamp.parts, stamp.parts) if saved.stamp.parts else []
        return "changed since the last grading: " + (", ".join(changed) or "the grader (an older version)")
    return None


def save_result(outputs: Outputs, result: StudentResult, stamp: Stamp, graded_at: str) -> None:
    """Write a student's feedback page, Gradescope JSON and saved result (last: it marks the student done).

    A page that cannot be made from the result is replaced by a plain one that says why; the grade is kept.
    """
    fit_result(result)  # every student-controlled text bounded (grading.budget), whoever made the result
    payload = {
        "fingerprint": stamp.fingerprint,
        "fingerprint_parts": stamp.parts,
        "graded_because": stamp.because,
        "graded_at": graded_at,
        "result": json.loads(result.to_json()),
    }
    try:
        page = feedback.feedback_html(result)
    except Exception as error:
        page = plain_page(
            f"Feedback for {result.student_id}",
            [result],
            f"the full feedback page could not be made ({type(error).__name__}: {error})",
        )
    try:
        gradescope = results_json(result, seconds=result.seconds)
    except Exception as error:
        gradescope = {
            "score": result.score,
            "output": f"the detailed results could not be made ({type(error).__name__}: {error})",
        }
    saved = json.dumps(payload, indent=1, sort_keys=True)
    if len(saved) > RESULT_BYTES:  # only the similarity answers can still be large: never the grade
        payload["result"]["answers"] = None
        saved = json.dumps(payload, indent=1, sort_keys=True)
    gradescope = json.dumps(gradescope, indent=1, ensure_ascii=False)
    if len(gradescope.encode("utf-8", "surrogatepass")) > GRADESCOPE_BYTES:
        gradescope = json.dumps({"score": result.score, "output": "the detailed results are too large to show"})
    if len(page.encode("utf-8", "surrogatepass")) > PAGE_BYTES:
        page = plain_page(f"Feedback for {result.student_id}", [result], "the full feedback page is too large")
    write_atomically(outputs.feedback_html(result.student_id), page)
    write_atomically(outputs.gradescope_json(result.student_id), gradescope)
    write_atomically(outputs.student_json(result.student_id), saved)


def grade_task(task: GradingTask, slot: warm.WarmSlot | None = None) -> None:
    """Runs in a forked child: grade one student and save the result (``slot``: this child's warm slot)."""
    student_id, folder, context, out_root, stamp, config = task[:6]
    student = None
    process_tree.become_subreaper()
    outputs = Outputs(Path(out_root))

    def on_alarm(signum, frame):
        raise TimeoutError(f"grading this student took longer than {STUDENT_TIMEOUT} s")

    signal.signal(signal.SIGALRM, on_alarm)
    signal.alarm(STUDENT_TIMEOUT)
    try:
        student = submissions.read_student_folder(folder, task.layout, student_id)  # the one walk of the folder
        answers = functools.partial(summarize, course=context.course)  # kept for the similarity stage
        result = apply_late_policy(
            grade_student(student_id, student, context, slot=slot, answers=answers), student, config
        )
    except Exception as error:  # our fault, not the student's: report, keep the batch going
        result = StudentResult(
            student_id=student_id,
            status=COULD_NOT_GRADE,
            reason=f"{type(error).__name__}: {error}",
            submission_hash=student.digest if student is not None else _hash_or_blank(folder, task.layout),
        )
        result.problems.append(traceback.format_exc(limit=3).strip().splitlines()[-1])
    finally:
        signal.alarm(0)
        process_tree.kill_descendants()
    try:
        save_result(outputs, result, stamp, time.strftime("%Y-%m-%d %H:%M:%S"))
    except Exception as error:  # the parent records this student from what it knows (record_death)
        print(one_line(f"could not save the result of {student_id}: {type(error).__name__}: {error}"), file=sys.stderr)


def _hash_or_blank(folder, layout=submissions.FOLDERS):
    try:
        return submissions.submission_hash(folder, layout)
    except Exception:  # the folder went away or cannot be listed: the next run grades it again anyway
        return ""


def record_death(task: GradingTask, problem: str) -> StudentResult:
    """The child grading a student died: save a 'could not grade' result that says why, and return it.

    Never raises: when even this result cannot be saved, it is returned with a note, and the run keeps
    it in memory for this run's gradebook and report.
    """
    student_id, folder, _, out_root, stamp, _ = task[:6]
    result = StudentResult(
        student_id=student_id,
        status=COULD_NOT_GRADE,
        reason=f"{problem}; nothing else was affected, run grade again to retry",
        submission_hash=_hash_or_blank(folder, task.layout),
    )
    try:
        save_result(Outputs(Path(out_root)), result, stamp, time.strftime("%Y-%m-%d %H:%M:%S"))
    except Exception as error:
        result.problems.append(
            f"this result could not be saved ({type(error).__name__}: {error}); it is in "
            "this run's gradebook and report only"
        )
    return result


@dataclass
class RunSummary:
    graded: list = field(default_factory=list)  # (student_id, score, max, status, seconds)
    skipped: list = field(default_factory=list)  # student ids whose saved result was reused
    results: list = field(default_factory=list)  # StudentResult of everyone in the gradebook
    reasons: dict = field(default_factory=dict)  # student id -> why it was (re-)graded
    kept: list = field(default_factory=list)  # graded earlier, not under this run's path: kept as saved
    ignored: list = field(default_factory=list)  # Skipped: entries of the submissions folder that are not students
    canary: object = None  # CanaryResult
    seconds: float = 0.0
    similarity: object = None  # similarity Findings (None: turned off, or it failed: see similarity_note)
    similarity_note: str = ""  # why the similarity stage wrote no findings
    similarity_seconds: float = 0.0  # wall time of the similarity stage
    similarity_cpu_seconds: float = 0.0  # its CPU time, this process and its finished workers
    layout: object = None  # submissions.ClassLayout: how the class was read, and why


def prewarm(course: Course) -> None:
    """Import and compute, once, everything the forked graders share read-only."""
    preload_hidden_suite(course)
    released_stubs(course.released)
    launcher.isolation()
    launcher.limits_mode_can_drop_root()


class UnknownStudents(ValueError):
    """``only`` named students who have no folder under the submissions path."""


def saved_student_ids(outputs: Outputs) -> list[str]:
    """Ids of every student with a saved result in ``outputs``."""
    ids = []
    for path in sorted((outputs.root / "students").glob("*.json")):
        try:
            ids.append(json.loads(read_capped(path))["result"]["student_id"])
        except (OSError, ValueError, KeyError, TypeError):
            continue
    return ids


def grade_class(
    path: str | Path,
    out_dir: str | Path,
    course: Course,
    jobs: int | None = None,
    options: GradingOptions = GradingOptions(),
    force: bool = False,
    progress: Progress | None = None,
    roster: tuple | list = (),
    only: tuple | list = (),
    announce: Callable[[str], None] | None = None,
    config: CourseConfig | None = None,
    runner: Runner | None = None,
    similarity: bool = True,
    layout: str | None = None,
    share_output: bool = False,
) -> RunSummary:
    """Grade every student under ``path`` into ``out_dir`` against ``course``; return a :class:`RunSummary`.

    ``roster``: student ids expected; those without a folder are reported missing.
    ``only``: grade just these students (always re-graded); everyone else keeps their saved result.
    ``announce``: called with a line of text when a step worth telling starts or ends (the canary).
    ``config``: a :class:`~autograder.reports.lateness.CourseConfig` with due dates and the late policy.
    ``runner``: how the students' tasks run (a :class:`Runner`; default: forks of this process, ``jobs``
    at a time, each with a warm slot when this machine has them).
    ``similarity``: compare the class's answers (:mod:`autograder.similarity`) and add the "Similar answers"
    section and ``similar_answers.csv``; a failure there costs that section only.
    The gradebook never shrinks: students graded earlier into ``out_dir`` stay in it, with their
    saved results, even when ``path`` no longer holds their folder (``RunSummary.kept`` names them).

    Raises
    ------
    CanaryFailed
        The reference solutions did not get full marks on this machine; nothing was written.
    UnknownStudents
        A student of ``only`` has no folder under ``path``; nothing was written.
    """
    started = time.monotonic()
    outputs = Outputs(Path(out_dir))
    found = submissions.scan_submissions(path, layout)
    students = found.files
    unknown = sorted(set(only) - {student_id for student_id, _ in students})
    if unknown:
        raise UnknownStudents(f"no submission folder under {path} for: {', '.join(unknown)}")
    cleanup.sweep_stale()  # the temporary folders of a grader that was killed mid-batch
    parts = fingerprint_parts(options, course)
    summary = RunSummary(ignored=found.skipped, layout=found.layout)
    # a cold start records the reference; another grader doing so on this machine is waited for, not repeated
    with recording_turn(course, announce) if not canary_cached(parts) else nullcontext():
        prewarm(course)
        if options.nbval and runner is None and not canary_cached(parts):
            # the notebook transcripts first (their runs side by side), so that the canary's notebook stage
            # replays them instead of running every kernel a third time; a lesson whose recording failed runs
            # its kernel
            record_notebook_calls(course, options, lessons=options.lessons)
        if announce:
            announce("canary: grading the reference solutions first (once per grader version)...")
        summary.canary = ensure_reference_passes(course, options, parts, submissions=path, output=out_dir)
    if announce:
        announce(describe_canary(summary.canary))
    set_output_sharing(outputs.root, share_output)
    for stale in outputs.root.glob("*/.*.tmp"):  # left by a run that was killed mid-write
        stale.unlink(missing_ok=True)
    if config is not None:
        parts["course config"] = hashlib.sha256(config.source.encode()).hexdigest()[:16]
        if config.ignore_file_times:
            parts["file times"] = "ignored (--ignore-mtimes)"
    stamp = Stamp(fingerprint(parts), parts)
    context = GradingContext(course, options)
    tasks = []
    for student_id, folder in students:
        if only and student_id not in only:
            summary.skipped.append(student_id)
            continue
        try:
            because = regrade_reason(
                load_saved(outputs, student_id),
                stamp,
                submissions.submission_hash(folder, found.layout.kind),
                force or bool(only),
            )
        except Exception as error:  # this student only: grade them, and say why
            because = f"graded: whether the submission changed could not be checked ({type(error).__name__})"
        if because is None:
            summary.skipped.append(student_id)
            continue
        summary.reasons[student_id] = because
        tasks.append(
            GradingTask(
                student_id,
                str(folder),
                context,
                str(outputs.root),
                replace(stamp, because=because),
                config,
                found.layout.kind,
            )
        )
    jobs = max(1, jobs or os.cpu_count() or 1)
    if progress:
        progress.start(len(tasks))

    unsaved = {}  # student id -> a result that could not be saved: it still goes into this run's reports

    def on_done(task, problem):
        saved = None if problem else load_saved(outputs, task.student_id)
        if saved is None:
            result = record_death(task, problem or "the grading process ended without saving a result")
            if load_saved(outputs, task.student_id) is None:
                unsaved[task.student_id] = result
        else:
            result = saved.result
        row = (result.student_id, result.score, result.max_score, result.status, result.seconds)
        summary.graded.append(row)
        if progress:
            progress.advance(row)

    if runner is not None:
        runner(grade_task, tasks, jobs, on_done, deadline_seconds=STUDENT_TIMEOUT + 120)
    elif tasks:
        jobs = min(jobs, len(tasks))
        with warm.SlotPool(jobs, options.limits, course.support) if warm.enabled() else nullcontext() as slots:
            learn_reference_in_sandbox(
                course.reference, course, options.limits, slots.slots[0] if slots else None, lessons=options.lessons
            )
            if options.nbval:  # the notebook stage's transcripts: a kernel run skipped when the calls agree
                record_notebook_calls(course, options, lessons=options.lessons)
            fork_each(grade_task, tasks, jobs, on_done, deadline_seconds=STUDENT_TIMEOUT + 120, slots=slots)
    if progress:
        progress.finish()
    submitted = {sid for sid, _ in students}
    earlier = set(saved_student_ids(outputs))
    summary.kept = sorted(earlier - submitted)
    everyone = submitted | earlier
    write_atomically(outputs.skipped, json.dumps([asdict(item) for item in found.skipped], indent=1))
    section = _similarity_section(found.layout, course, outputs, summary, sorted(submitted)) if similarity else ""
    summary.results = write_reports(outputs, course, sorted(everyone | set(roster)), everyone, unsaved, section)
    summary.seconds = time.monotonic() - started
    return summary


def collect_results(
    outputs: Outputs,
    student_ids: list[str],
    submitted: set[str] | None = None,
    unsaved: dict[str, StudentResult] | None = None,
) -> tuple[list[StudentResult], dict[str, str]]:
    """Saved results for ``student_ids``; a student without one is missing or not finished.

    ``unsaved``: ``{student_id: StudentResult}`` of this run that could not be saved, used when no saved
    result can be read.
    """
    results, graded_at = [], {}
    for student_id in student_ids:
        path = outputs.student_json(student_id)
        try:
            data = json.loads(read_capped(path))
            results.append(StudentResult.from_json(json.dumps(data["result"])))
            graded_at[student_id] = data.get("graded_at", "")
        except (OSError, ValueError, KeyError, TypeError):
            if unsaved and student_id in unsaved:
                results.append(unsaved[student_id])
            elif submitted is not None and student_id not in submitted:
                results.append(StudentResult(student_id=student_id, status=MISSING, reason="no submission folder"))
            else:
                results.append(
                    StudentResult(
                        student_id=student_id,
                        status=COULD_NOT_GRADE,
                        reason="no saved result: the run was interrupted before "
                        "this student was graded; run grade again",
                    )
                )
    return results, graded_at


def load_skipped(outputs: Outputs) -> list[submissions.Skipped]:
    """The entries of the submissions folder that the last run did not grade, as ``Skipped``."""
    try:
        return [submissions.Skipped(**item) for item in json.loads(outputs.skipped.read_text(encoding="utf-8"))]
    except (OSError, ValueError, TypeError):
        return []


def saved_answers(outputs: Outputs, student_ids: list[str]) -> dict[str, dict | None]:
    """``{student_id: answers}`` kept by each student's grading process for the similarity stage (their saved
    result, read with its size cap), or None for a student without them.

    >>> saved_answers(Outputs(Path("out")), ["ada"])        # doctest: +SKIP
    {'ada': {'rot_z': {'source': 'def rot_z(angle): ...', 'normalised': ..., 'offsets': [...]}}}
    """
    found = {}
    for student_id in student_ids:
        try:
            answers = json.loads(read_capped(outputs.student_json(student_id)))["result"].get("answers")
        except (OSError, ValueError, KeyError, TypeError, AttributeError):
            answers = None
        found[student_id] = answers if isinstance(answers, dict) else None
    return found


def _similarity_section(path, course, outputs, summary, student_ids=()):
    """Run the similarity stage on the class under ``path``: write its CSV and page into ``outputs``,
    keep the findings in ``summary`` and return the report's section (a short note if it failed). The
    answers are those the students' grading processes kept (:func:`saved_answers`); nothing of a student's
    is parsed in this process."""
    from autograder.similarity.report import similar_answers_html
    from autograder.similarity.stage import similarity_of_class, write_findings

    started, cpu = time.monotonic(), cpu_seconds()
    try:
        summary.similarity = similarity_of_class(path, course, summaries=saved_answers(outputs, list(student_ids)))
        write_findings(summary.similarity, outputs.root, write_atomically)
        section = similar_answers_html(summary.similarity)
    except Exception as error:  # the grades do not depend on it
        summary.similarity = None
        summary.similarity_note = f"the similarity stage failed ({type(error).__name__}: {error})"
        section = f"<h2>Similar answers</h2><p>Not available: {one_line(summary.similarity_note, 300)}.</p>"
    summary.similarity_seconds = time.monotonic() - started
    summary.similarity_cpu_seconds = cpu_seconds() - cpu
    return section


def cpu_seconds() -> float:
    """User and system CPU seconds of this process and of its children that have finished (a stage's
    forked workers): what a stage costs on a shared machine, where its wall time depends on the load."""
    own, children = resource.getrusage(resource.RUSAGE_SELF), resource.getrusage(resource.RUSAGE_CHILDREN)
    return own.ru_utime + own.ru_stime + children.ru_utime + children.ru_stime


def write_reports(
    outputs: Outputs,
    course: Course,
    student_ids: list[str],
    submitted: set[str] | None = None,
    unsaved: dict[str, StudentResult] | None = None,
    extra_section: str = "",
) -> list[StudentResult]:
    """Write grades.csv and report.html for ``student_ids``; return their results.

    ``extra_section``: HTML added to the report (the similarity stage's "Similar answers").

    The report is always written: if the full page cannot be made, a plain one lists every student's
    status and says why.
    """
    from autograder.reports.class_report import class_report_html

    results, graded_at = collect_results(outputs, student_ids, submitted, unsaved)
    catalog = course.catalog
    write_atomically(outputs.gradebook, gradebook_csv(results, catalog, graded_at))
    try:
        linked = {r.student_id for r in results if outputs.feedback_html(r.student_id).is_file()}
        page = class_report_html(
            results, catalog, skipped=load_skipped(outputs), linked=linked, extra_sections=[extra_section]
        )
    except Exception as error:
        page = plain_page(
            "Class report", results, f"the full report could not be made ({type(error).__name__}: {error})"
        )
    write_atomically(outputs.report, page)
    return results
