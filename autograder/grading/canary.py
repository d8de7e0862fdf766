"""The canary: before a batch, the reference solutions are graded through the whole pipeline.

The reference must get full marks on every exercise and every notebook
stage. If it does not, some stage is broken on this machine (a sandbox that
cannot import ``coursekit``, a kernel that does not start, a changed
library...) and every student would be graded wrongly: the batch stops
before anything is written, with a message naming the lesson and the stage.

A passing canary is remembered per grader fingerprint
(:mod:`autograder.grading.fingerprint`) in a small cache folder, so it costs one
student's grading once, not once per run.

Before that, and on every run, the canary looks at the sandbox's world from inside
(:func:`check_sandbox_view`): if the course's hidden suite, its masters, the submissions
folder, the output folder, the grader's cache folder or the grader's checkout can be seen
from a sandbox (by its path, or a copy of a secret file anywhere), it refuses to grade.

Examples
--------
>>> ensure_reference_passes(course, GradingOptions(), parts)   # doctest: +SKIP
CanaryResult(cached=True, seconds=0.0, ...)
>>> check_sandbox_view(course, submissions="class/", output="out/").line()       # doctest: +SKIP
'project files out of reach (checked from inside a sandbox: 186 paths bound, 21,873 entries seen; ...)'
"""

from __future__ import annotations

import hashlib
import json
import os
import shutil
import subprocess
import sys
import time
from dataclasses import dataclass, field, replace
from pathlib import Path

from autograder.grading.fingerprint import cache_dir, fingerprint, write_private
from autograder.grading.options import GradingOptions
from autograder.grading.results import StudentResult
from autograder.lessons.course import Course
from autograder.sandbox import allowlist, cleanup, launcher
from autograder.sandbox.forking import fork_each


class CanaryFailed(Exception):
    """The reference solutions did not get full marks: grading on this machine cannot be trusted."""


class SandboxExposed(CanaryFailed):
    """A sandbox can see what students must not: the hidden suite, the masters, classmates' work, the output,
    the grader's cache or checkout. Nothing is graded."""


@dataclass
class CanaryResult:
    cached: bool
    seconds: float
    score: float = 0.0
    max_score: float = 0.0


def describe_canary(canary: CanaryResult) -> str:
    """One line for the run's output."""
    if canary.cached:
        return "canary: the reference solutions got full marks with this grader before (cached)"
    return (
        f"canary: the reference solutions got full marks ({canary.score:g}/{canary.max_score:g}) "
        f"in {canary.seconds:.1f} s"
    )


SECRET_MIN_BYTES = 200  # smaller secret files (an empty __init__.py) are compared by path only
SECRET_MAX_FILES = 5_000  # files of one secret folder compared by content, at most


@dataclass
class ViewCheck:
    """What :func:`check_sandbox_view` found: ``checked`` names what was looked for, ``binds`` how many paths
    the sandbox's allow-list binds, ``entries`` how many the probe saw inside; ``mode`` is ``limits`` when there
    is no sandbox world to look at (resource limits only)."""

    mode: str
    checked: list[str] = field(default_factory=list)
    binds: int = 0
    entries: int = 0
    seconds: float = 0.0

    def line(self) -> str:
        """The isolation line's claim, from these findings."""
        if self.mode != "namespaces":
            return "project files readable (resource limits only)"
        return (
            f"project files out of reach (checked from inside a sandbox: {self.binds} paths bound, "
            f"{self.entries:,} entries seen; not visible: {', '.join(self.checked)})"
        )


def _secret_paths(course, submissions, output):
    """``{label: host path}`` of what no sandbox may see."""
    labels = {
        "the course's hidden suite": course.hidden_suite,
        "the course's masters (solutions)": course.solutions,
        "the grader's cache folder": cache_dir(),
        "the grader's checkout": launcher.GRADER_ROOT,
    }
    if submissions is not None:
        labels["the submissions folder"] = Path(submissions)
    if output is not None:
        labels["the output folder"] = Path(output)
    return labels


def _secret_files(course):
    """``[(label, path, size)]`` of files whose copies no sandbox may see: the hidden suite, the masters, the
    grader's wrong and right answers (``autograder/mistakes``). Never a student's file: a student could hand in
    a copy of a file every sandbox sees (a package's, coursekit's) and stop the class's grading; where the
    submissions are is checked by path, and against ``coursekit``, which every sandbox gets a copy of."""
    found = []

    def add(label, folder, pattern, limit=SECRET_MAX_FILES):
        if folder is None or not Path(folder).is_dir():
            return
        count = 0
        for root, dirs, names in os.walk(folder):  # links are never followed
            dirs[:] = [d for d in dirs if d != "__pycache__" and not d.startswith(".")]
            for name in names:
                if not Path(name).match(pattern):
                    continue
                path = os.path.join(root, name)
                try:
                    info = os.lstat(path)
                except OSError:
                    continue
                if info.st_size >= SECRET_MIN_BYTES and os.path.isfile(path) and not os.path.islink(path):
                    found.append((label, path, info.st_size))
                    count += 1
                    if count >= limit:
                        return

    add("the course's hidden suite", course.hidden_suite, "*")
    for master in sorted(course.solutions.glob("[0-9][0-9]_*.ipynb")):
        if master.is_file():
            found.append(("the course's masters (solutions)", str(master), master.stat().st_size))
    add("the grader's answers (autograder/mistakes)", launcher.GRADER_ROOT / "autograder" / "mistakes", "*.py")
    add("the grader's checkout (its hidden suite)", launcher.GRADER_ROOT / "autograder" / "hidden", "*.py")
    return found


def _sha256(path):
    digest = hashlib.sha256()
    with open(path, "rb") as file:
        for block in iter(lambda: file.read(1 << 20), b""):
            digest.update(block)
    return digest.hexdigest()


def _expected_children(view_paths, folder):
    """Names the allow-list itself puts directly in ``folder`` (a parent it makes for its own binds)."""
    prefix = folder.rstrip("/") + "/"
    return {p[len(prefix) :].split("/", 1)[0] for p in view_paths if p.startswith(prefix)}


_CHECKED: dict = {}


def check_sandbox_view(
    course: Course, submissions: str | Path | None = None, output: str | Path | None = None, timeout: float = 120
) -> ViewCheck:
    """Look at a sandbox's world from inside, as a student's code would (same allow-list, same ``/sandbox``
    with the course's ``coursekit``); raise :class:`SandboxExposed` if any of the course's hidden suite, its
    masters, the ``submissions`` folder, the ``output`` folder, the grader's cache folder or its checkout is
    visible there, by path or by a copy of one of their files. Checked once per process for the same folders.

    >>> check_sandbox_view(this_course(), "class", "out").mode                      # doctest: +SKIP
    'namespaces'
    """
    key = (course, str(submissions), str(output))
    if key in _CHECKED:
        return _CHECKED[key]
    mode, _ = launcher.isolation()
    if mode != "namespaces":
        return ViewCheck(mode=mode)
    started = time.monotonic()
    labels = _secret_paths(course, submissions, output)
    paths = {}
    for label, path in labels.items():
        for variant in {os.path.abspath(path), os.path.realpath(path)}:
            paths[variant] = label
    secrets = _secret_files(course)
    spec = {"paths": sorted(paths), "sizes": sorted({size for _, _, size in secrets})}
    with cleanup.private_folder_for("view") as base:
        sandbox_dir, scratch_dir = launcher.prepare_dirs(base, course.support)
        shutil.copy2(Path(launcher.__file__).resolve().parent / "child" / "view_probe.py", sandbox_dir)
        (sandbox_dir / "view_secrets.json").write_text(json.dumps(spec), encoding="utf-8")
        for name in ("view_probe.py", "view_secrets.json"):
            os.chmod(sandbox_dir / name, 0o644)
        program = [sys.executable, "-I", "-B", "/sandbox/view_probe.py", "/sandbox/view_secrets.json"]
        try:
            process = launcher.spawn(program, sandbox_dir, scratch_dir, launcher.Limits(), stdin=subprocess.DEVNULL)
            try:
                stdout, _ = process.communicate(timeout=timeout)
            finally:
                launcher.terminate(process)
            found = json.loads(stdout.decode("utf-8", "replace").strip().splitlines()[-1])
        except (OSError, subprocess.SubprocessError, ValueError, IndexError) as error:
            raise SandboxExposed(
                f"the sandbox's view could not be checked from inside ({type(error).__name__}: {error}); "
                "no student was graded (nothing was written or overwritten)"
            ) from None
    view = allowlist.sandbox_view()
    view_paths = view.paths()
    problems = []
    support = os.path.realpath(course.support)
    for label, path in labels.items():  # coursekit is copied into every sandbox, at /sandbox/coursekit
        real = os.path.realpath(path)
        if real == support or real.startswith(support + os.sep):
            inside = "/sandbox/coursekit" + real[len(support) :]
            problems.append(f"{label}: {path} is inside the course's coursekit, copied into every sandbox ({inside})")
    for path, entries in sorted(found.get("present", {}).items()):
        bound = any(path == dest or path.startswith(dest.rstrip("/") + "/") for _, dest in view.binds)
        extra = sorted(set(entries) - _expected_children(view_paths, path))
        if bound or extra or not any(p.startswith(path.rstrip("/") + "/") for p in view_paths):
            shown = f" (holding {', '.join(extra[:5])}{' ...' if len(extra) > 5 else ''})" if extra else ""
            problems.append(f"{paths[path]}: {path}{shown}")
    by_size: dict[int, list] = {}
    for label, path, size in secrets:
        by_size.setdefault(size, []).append((label, path))
    digests: dict[str, tuple[str, str]] = {}
    for size in {int(c[1]) for c in found.get("candidates", [])}:
        for label, path in by_size.get(size, []):
            try:
                digests.setdefault(_sha256(path), (label, path))
            except OSError:
                pass
    copies: dict[str, list[str]] = {}
    for inside, _, digest in found.get("candidates", []):
        if digest in digests:
            label, path = digests[digest]
            copies.setdefault(label, []).append(f"{label}: a copy of {path} is at {inside}")
    for label, lines in copies.items():
        problems += lines[:3] + ([f"{label}: and {len(lines) - 3} more copies"] if len(lines) > 3 else [])
    if problems:
        raise SandboxExposed(
            "student code could see what it must not, so no student was graded (nothing was written or "
            "overwritten). Seen from inside a sandbox:\n  "
            + "\n  ".join(problems[:20])
            + ("\n  ..." if len(problems) > 20 else "")
            + "\nMove these out of the sandbox's view: a sandbox sees only the Python installation's standard "
            "library, the packages it needs, the course's coursekit and its own /tmp (SECURITY.md)."
        )
    check = ViewCheck(
        mode=mode,
        checked=list(dict.fromkeys(labels)),
        binds=len(view.binds) + len(view.links),
        entries=int(found.get("entries", 0)),
        seconds=time.monotonic() - started,
    )
    _CHECKED[key] = check
    return check


def _marker(parts):
    return cache_dir() / f"canary-{fingerprint(parts)}.json"


def canary_cached(parts: dict[str, str]) -> bool:
    """Has a canary of these fingerprint ``parts`` passed on this machine before (so it will not run now)?"""
    return _marker(parts).exists()


def shortfalls(result: StudentResult) -> list[str]:
    """One line per lesson stage where ``result`` is below full marks (empty when it has full marks)."""
    lines = []
    if result.reason:
        lines.append(f"{result.status}: {result.reason}")
    for lesson in result.lessons:
        if lesson.status != "graded":
            lines.append(f"lesson {lesson.number}, reading the notebook: {lesson.reason}")
            continue
        for exercise in lesson.exercises:
            if exercise.points < exercise.max_points:
                failed = next((c for c in exercise.checks if not c.passed), None)
                why = f"{failed.description}: {failed.reason}" if failed else "; ".join(exercise.notes)
                lines.append(
                    f"lesson {lesson.number}, hidden suite, {exercise.name} "
                    f"({exercise.points:g}/{exercise.max_points:g}): {why}"
                )
        run = lesson.run
        if run is not None and run.points < run.max_points:
            lines.append(
                f"lesson {lesson.number}, notebook stage (nbval): " + ("; ".join(run.failures[:2]) or run.status)
            )
    return lines


def _grade_reference(course, options, folder, target, slot=None):
    """Runs in a fork, like a student's grading: grade the reference and write its result to ``target``."""
    from autograder.grading.context import GradingContext
    from autograder.grading.pipeline import grade_student
    from autograder.sandbox import process_tree

    process_tree.become_subreaper()
    try:
        result = grade_student("reference solutions (canary)", folder, GradingContext(course, options), slot=slot)
    finally:
        process_tree.kill_descendants()
    Path(target).write_text(result.to_json(), encoding="utf-8")


def _expected_cost(course, lesson):
    """A lesson's canary grading, roughly: the calls its notebook transcript replays, if one is known (a lesson
    whose kernel runs counts as many)."""
    from autograder.grading import notebook_calls

    learned = notebook_calls.memo(course)
    if lesson not in learned:
        return 0
    transcript = learned[lesson]
    return 10_000 if transcript is None else len(transcript.calls)


def _joined(results: list[StudentResult]) -> StudentResult:
    """The gradings of the reference's lessons, graded apart, as one result (lessons in order, reasons joined)."""
    first = next((result for result in results if result.reason), results[0])
    return replace(
        first,
        reason="; ".join(result.reason for result in results if result.reason),
        lessons=sorted((lesson for result in results for lesson in result.lessons), key=lambda lesson: lesson.number),
    )


def ensure_reference_passes(
    course: Course,
    options: GradingOptions,
    parts: dict[str, str],
    timeout: float = 900,
    submissions: str | Path | None = None,
    output: str | Path | None = None,
) -> CanaryResult:
    """Check the sandbox's view (:func:`check_sandbox_view`, with the run's ``submissions`` and ``output``
    folders), then grade ``course``'s reference through the full pipeline unless a passing canary is cached;
    raise :class:`CanaryFailed` (:class:`SandboxExposed` for the view) naming each failing lesson and stage."""
    check_sandbox_view(course, submissions, output)
    marker = _marker(parts)
    if marker.exists():
        return CanaryResult(cached=True, seconds=0.0)
    from autograder.lessons.hand_ins import write_reference_submission

    started = time.monotonic()
    lessons = list(options.lessons) or [lesson.number for lesson in course.catalog.graded_lessons]
    lessons.sort(key=lambda number: -_expected_cost(course, number))  # the longest first: both CPUs end together
    if not lessons:
        raise CanaryFailed("the course has no graded lesson: there is nothing to grade")
    with cleanup.private_folder_for("canary") as base:
        folder = write_reference_submission(course, Path(base) / "reference", lessons=options.lessons)
        deaths = {}
        fork_each(  # one grading per lesson, side by side: the same pipeline, its lessons graded apart
            lambda number, slot: _grade_reference(
                course, replace(options, lessons=(number,)), folder, Path(base) / f"{number}.json", slot
            ),
            lessons,
            jobs=max(1, min(len(lessons), len(os.sched_getaffinity(0)))),
            on_done=deaths.__setitem__,
            deadline_seconds=timeout,
        )
        results = []
        for number in lessons:
            target = Path(base) / f"{number}.json"
            if deaths.get(number) or not target.exists():
                raise CanaryFailed(
                    f"grading the reference solutions failed (lesson {number}): "
                    f"{deaths.get(number) or 'no result was written'}; "
                    "no student was graded (nothing was written or overwritten)"
                )
            results.append(StudentResult.from_json(target.read_text(encoding="utf-8")))
        result = _joined(results)
    problems = shortfalls(result)
    if problems or result.max_score <= 0:
        raise CanaryFailed(
            f"the reference solutions scored {result.score:g}/{result.max_score:g} on this machine, so a "
            "stage of the grader is broken here and no student was graded (nothing was written or "
            "overwritten). Where the reference lost points:\n  " + "\n  ".join(problems or ["no points at all"])
        )
    seconds = time.monotonic() - started
    try:
        write_private(
            marker, json.dumps({"parts": parts, "score": result.score, "seconds": round(seconds, 1)}, indent=1)
        )
    except OSError:
        pass  # a read-only home: the canary simply runs again next time
    return CanaryResult(cached=False, seconds=seconds, score=result.score, max_score=result.max_score)
