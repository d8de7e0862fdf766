"""``python -m autograder``: release the course, record outputs, grade a class.

Every command that reads a course takes ``--course DIR`` (a course folder, see
docs/AUTHORING.md "Write your own course"; default: this repository's course).

Commands
--------
new-course DIR
    Write a small, working course to start your own from (two lessons).
release [--check]
    Regenerate ``course/`` from ``solutions/``; ``--check`` only verifies.
record [--only NN ...]
    Re-record the demonstration outputs stored in the masters.
grade [PATH] --out DIR [--jobs N] [--no-nbval] [--lessons NN ...] [--roster FILE]
      [--nbgrader-db PATH] [--force] [--student ID ...] [--config late.toml] [--ignore-mtimes]
      [--cluster ADDRESS]
    Grade every student folder in PATH (or the bundled sample class); with
    --student, re-grade only those. The gradebook never loses a student.
    --ignore-mtimes: no lateness from file times, only from timestamp.txt.
    Exit status 3 when the canary fails (nothing is written).
status --out DIR [--roster FILE]
    Who is graded, who could not be graded and why, who is missing; why a
    student was re-graded; a warning when student code ran with limits only.
nbgrader-course --out DIR [--lessons NN ...]
    Write a stock nbgrader course from the masters (one assignment per lesson).
handout --out course.zip
    Pack what students get: the released notebooks, coursekit, their install
    list (no instructor tools) and a README.
export --out DIR --to canvas [--roster roster.csv] [--file PATH]
    Write the saved grades as an LMS import file (Canvas; see autograder/reports/exports/).
canary [--lessons NN ...] [--no-nbval]
    Grade the reference solutions through the whole pipeline; exit 3 unless
    they get full marks. ``grade`` runs it first (cached per grader fingerprint).
gradescope --out autograder.zip [--lessons NN ...] [--visibility V]
    Build a Gradescope autograder bundle (setup.sh, run_autograder, the grader).
preview NOTEBOOK [--figures DIR]
    Run a notebook top to bottom; report errors, warnings and check cells;
    save every figure as a PNG to look at (for authors).
course-stats [--markdown | --catalog]
    What the exercises ask for, per lesson: exercises and points by kind (transcribe, assemble,
    derive, design, diagnose), the share of points that ask for thinking, estimated minutes;
    --catalog prints docs/EXERCISES.md.
book --out DIR
    Build the book: the solved lessons, executed, as a static website
    (open DIR/index.html in a browser; no Python needed to read it).
"""

import sys

# Speed: nbformat -> jsonschema imports rfc3987_syntax when it is installed, which builds a grammar
# at import time (seconds of CPU for every command). It only checks the "iri" string format, which no
# notebook schema uses; without it jsonschema does not register that check (as sandbox/child/nbval_runner.py).
sys.modules.setdefault("rfc3987_syntax", None)

import argparse
import os
from collections import Counter
from pathlib import Path

from autograder.lessons.untrusted_text import one_line
from autograder.reports.exports import EXPORTERS

USAGE_ERROR = 2  # a mistake on the command line or in a file it names: nothing was done
INTERRUPTED = 130  # Ctrl-C, as a shell reports a process ended by SIGINT
CLOSED_PIPE = 141  # the reader of our output went away (`status | head`), as for SIGPIPE


class UsageError(ValueError):
    """A mistake the instructor can fix on the command line; ``main`` prints it as one line, exit status 2."""


def _course(args):
    """The course a command works on: ``--course DIR``, else this repository's; a folder that is not a course
    raises :class:`UsageError`."""
    from autograder.lessons.course import Course, CourseError
    from autograder.lessons.paths import this_course

    try:
        return Course.at(args.course) if getattr(args, "course", None) else this_course()
    except CourseError as error:
        raise UsageError(str(error)) from None


def _lesson_numbers(given, course):
    """``given`` lesson numbers as the catalog spells them: "3" is read as "03" (said on stderr); an unknown one
    raises :class:`UsageError` naming the valid ones."""
    if not given:
        return ()
    valid = [lesson.number for lesson in course.catalog.graded_lessons]
    numbers = []
    for number in given:
        padded = number.zfill(2) if number.isdigit() and len(number) < 2 else number
        if padded not in valid:
            raise UsageError(f"unknown lesson {number!r}: the graded lessons are {' '.join(valid)}")
        if padded != number:
            print(f"--lessons {number} read as {padded}", file=sys.stderr)
        numbers.append(padded)
    return tuple(dict.fromkeys(numbers))


def _positive_jobs(text):
    """``--jobs``: a whole number of at least 1."""
    try:
        jobs = int(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"a whole number of parallel graders, not {text!r}") from None
    if jobs < 1:
        raise argparse.ArgumentTypeError(f"must be 1 or more (got {jobs}); leave it out to use every core")
    return jobs


SUBMISSIONS_LAYOUT = (
    "a submissions folder holds one folder per student (SUBMISSIONS/anna/01_frames.ipynb, "
    "SUBMISSIONS/ben/...), or is nbgrader's submitted/<student>/<assignment>/ layout"
)


def _require_students(path, layout=None):
    """Raise :class:`UsageError` when ``path`` holds no student folder, saying what one looks like, and when
    ``path`` looks like a single student's folder (notebooks of its own, or only nbgrader assignment folders).
    ``layout``: the one declared (``grade --layout``), else detected from the instructor's markers."""
    import re

    from autograder.grading.submissions import scan_submissions

    students = [student_id for student_id, _ in scan_submissions(path, layout).files]
    if students and not all(re.fullmatch(r"lesson\d\d", student_id) for student_id in students):
        return
    if students or any(child.suffix == ".ipynb" for child in path.iterdir()):
        raise UsageError(
            f"{path} looks like one student's folder ({'assignment folders' if students else 'notebooks'}"
            f", no student folders): give the folder that holds every student's folder; "
            f"{SUBMISSIONS_LAYOUT}"
        )
    raise UsageError(f"no student folders in {path}: {SUBMISSIONS_LAYOUT}")


def _cmd_new_course(args):
    from autograder.authoring.new_course import write_course
    from autograder.lessons.paths import this_course

    try:
        root = write_course(Path(args.folder), this_course().support)
    except ValueError as error:
        raise UsageError(str(error)) from None
    print(
        f"wrote a new course in {root}: two lessons to grow from. Next: python -m autograder release "
        f'--course {root} (docs/AUTHORING.md, "Write your own course")'
    )
    return 0


def _cmd_release(args):
    from autograder.authoring.release import release, stale_files

    course = _course(args)
    if args.check:
        problems = stale_files(course.solutions, course.released)
        for path, reason in problems:
            print(f"{path}: {reason}")
        if problems:
            print(
                f"course/ is out of date: {len(problems)} file(s). Run: python -m autograder release"
                + (f" --course {args.course}" if args.course else "")
            )
            return 1
        print("course/ and solutions/ are in sync.")
        return 0
    written = release(course.solutions, course.released)
    for path in written:
        print(f"wrote {path}")
    print(f"release done: {len(written)} file(s) changed.")
    return 0


def _cmd_contracts(args):
    from autograder.authoring.contracts_file import CONTRACTS_FILE, write_contracts

    course = _course(args)
    in_sync, problems = write_contracts(course.solutions, check=args.check)
    for problem in problems:
        print(f"cannot read the docstring of {problem}")
    path = course.solutions / CONTRACTS_FILE
    if not in_sync:
        print(f"{path} differs from the masters' docstrings. Run: python -m autograder contracts")
        return 1
    print(f"{path}: " + ("in sync with the masters' docstrings." if args.check else "written."))
    return 1 if problems else 0


def _cmd_record(args):
    from autograder.authoring.record import RecordingFailed, record_outputs

    try:
        changed = record_outputs(_course(args).solutions, only=args.only)
    except RecordingFailed as error:
        print(f"record failed: {error}", file=sys.stderr)
        return 1
    for path in changed:
        print(f"recorded {path}")
    course = f" --course {args.course}" if args.course else ""
    print(f"record done: {len(changed)} master(s) changed. Run `python -m autograder release{course}` next.")
    return 0


def _print_table(results, problems_shown=3):
    """The gradebook as a table (with a ``late`` column when anyone lost points for lateness); under a
    student graded with problems, the problems themselves.
    Student text is shown escaped, one line each, bounded (autograder/lessons/untrusted_text.py)."""
    from autograder.reports.lateness import late_summary

    ids = [one_line(r.student_id, 40) for r in results]
    width = max([len("student")] + [len(i) for i in ids])
    late = [late_summary(r) for r in results]
    late_width = max(len(cell) for cell in late + ["late"]) if any(late) else 0
    header = f"{'late':<{late_width}}  " if late_width else ""
    print(f"{'student':<{width}}  {'score':>13}  {header}status")
    for shown_id, r, late_cell in zip(ids, results, late):
        score = f"{r.score:g} / {r.max_score:g}" if r.max_score else "—"
        status = one_line(r.status + (f": {r.reason}" if r.reason else ""))
        late_cell = f"{late_cell:<{late_width}}  " if late_width else ""
        print(f"{shown_id:<{width}}  {score:>13}  {late_cell}{status}")
        for problem in r.problems[:problems_shown]:
            print(f"{'':<{width}}  {'':>13}    - {one_line(problem, 160)}")
        if len(r.problems) > problems_shown:
            print(
                f"{'':<{width}}  {'':>13}    - and {len(r.problems) - problems_shown} more "
                "(see the student's feedback page)"
            )


def _print_skipped(ignored, results, shown=20):
    """What was not graded: entries of the submissions folder (``ignored``) and, per student, what the
    walk of their folder skipped; at most ``shown`` lines of each (``status`` lists them all)."""
    inside = [r for r in results if r.skipped]
    sections = [
        (
            f"not graded: {len(ignored)} entr{'y' if len(ignored) == 1 else 'ies'} of the submissions folder that are "
            "not student folders:",
            [one_line(item.line(), 200) for item in ignored],
        ),
        (
            f"not read: {len(inside)} student folder(s) hold entries the grader skipped (hidden, links, too deep):",
            [f"{one_line(r.student_id, 40)}: {one_line('; '.join(r.skipped), 200)}" for r in inside],
        ),
    ]
    if ignored or inside:
        print()
    for title, lines in sections:
        if lines:
            print(title)
            for line in lines[:shown]:
                print(f"  {line}")
            if len(lines) > shown:
                print(f"  and {len(lines) - shown} more (`status` lists them all)")


def _print_lateness(results):
    """Under the table: who was late, each lesson's due date (course timezone), and a loud warning when the
    hand-in times are file times that look like a copy (autograder/reports/copied_times.py)."""
    from autograder.reports.copied_times import copied_times_warning
    from autograder.reports.lateness import due_dates, late_summary

    late = [r for r in results if late_summary(r)]
    due = due_dates(results)
    if due:
        print(f"\ndue: {due}; {len(late)} of {len(results)} students lost points for lateness (column late)")
    warning = copied_times_warning(results)
    if warning:
        print(f"\nWARNING: {warning}")


def _read_roster(path):
    """Roster ids from ``path`` (plain ids or a CSV; see autograder/reports/roster.py); a roster that cannot be
    used raises :class:`UsageError`."""
    from autograder.reports.roster import RosterError, read_roster

    try:
        return tuple(entry.student_id for entry in read_roster(path))
    except RosterError as error:
        raise UsageError(str(error)) from None


def _cmd_canary(args):
    from autograder.batch.class_run import prewarm
    from autograder.grading.canary import CanaryFailed, check_sandbox_view, describe_canary, ensure_reference_passes
    from autograder.grading.fingerprint import fingerprint_parts
    from autograder.grading.pipeline import GradingOptions
    from autograder.sandbox import launcher

    course = _course(args)
    args.lessons = _lesson_numbers(args.lessons, course)
    try:  # the sandbox's view, checked from inside (the isolation line says what it found)
        print(launcher.describe_isolation(check_sandbox_view(course).line()))
    except CanaryFailed as error:
        print(f"error: canary failed: {error}", file=sys.stderr)
        return 3
    options = GradingOptions(nbval=not args.no_nbval, lessons=tuple(args.lessons))
    prewarm(course)
    try:
        print(describe_canary(ensure_reference_passes(course, options, fingerprint_parts(options, course))))
    except CanaryFailed as error:
        print(f"error: canary failed: {error}", file=sys.stderr)
        return 3
    return 0


def _cmd_grade(args):
    from autograder.batch.class_run import UnknownStudents, grade_class
    from autograder.batch.progress import Progress
    from autograder.grading.canary import CanaryFailed, check_sandbox_view
    from autograder.grading.pipeline import GradingOptions
    from autograder.integrations.cluster import ClusterError
    from autograder.reports.lateness import ConfigError, load_config
    from autograder.sandbox import launcher, warm

    out = Path(args.out)
    course = _course(args)
    args.lessons = _lesson_numbers(args.lessons, course)
    roster = _read_roster(args.roster)
    try:
        lessons = [lesson.number for lesson in course.catalog.graded_lessons]
        config = load_config(args.config, lessons) if args.config else None
    except ConfigError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    path = args.path
    if path is None:
        from autograder.authoring.sample_class import build_sample_class

        if args.course:
            raise UsageError(
                "give the submissions folder to grade: the bundled sample class is written for this "
                "repository's course only"
            )
        path = out / "sample_class"
        build_sample_class(path, course, lessons=tuple(args.lessons))
        print(f"No PATH given: grading the bundled sample class, written to {path}")
    path = Path(path)
    if not path.is_dir():
        print(f"error: {path} is not a folder of student submissions", file=sys.stderr)
        return 2
    _require_students(path, args.layout)
    from autograder.grading.submissions import detect_layout

    try:  # the sandbox's view, checked from inside with this run's folders (grade_class's canary checks it too)
        print(launcher.describe_isolation(check_sandbox_view(course, submissions=path, output=out).line()))
    except CanaryFailed as error:
        print(f"error: canary failed: {error}", file=sys.stderr)
        return 3
    print(one_line(detect_layout(path, args.layout).line(), 400))  # after the isolation line, which comes first
    if not args.cluster and warm.enabled():
        print(
            "sandbox slots: each grading process keeps one warm sandbox whose workers are forked fresh for "
            'every student and reset between students (SECURITY.md, "Warm slots"; AUTOGRADER_WARM=0 turns '
            "them off)"
        )
    options = GradingOptions(nbval=not args.no_nbval, lessons=tuple(args.lessons))
    if args.ignore_mtimes:  # lateness only from timestamp.txt (autograder/reports/copied_times.py)
        from dataclasses import replace

        from autograder.reports.lateness import CourseConfig

        config = replace(config or CourseConfig(), ignore_file_times=True)
    runner = None
    if args.cluster:  # students become Dask tasks (autograder/integrations/cluster.py, docs/CLUSTER.md)
        from autograder.integrations.cluster import connect

        try:
            runner = connect(args.cluster, course, options, announce=lambda line: print(line, flush=True))
        except ClusterError as error:
            print(f"error: {error}", file=sys.stderr)
            return 2
    try:
        summary = grade_class(
            path,
            out,
            course,
            jobs=args.jobs,
            options=options,
            force=args.force,
            progress=Progress(sys.stderr),
            roster=roster,
            only=tuple(args.student),
            announce=lambda line: print(line, flush=True),
            config=config,
            runner=runner,
            similarity=not args.no_similarity,
            layout=args.layout,
            share_output=args.share_output,
        )
    except CanaryFailed as error:
        print(f"error: canary failed: {error}", file=sys.stderr)
        return 3
    except UnknownStudents as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    except ClusterError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    finally:
        if runner is not None:
            runner.close()
    print()
    _print_table(summary.results)
    _print_lateness(summary.results)
    print()
    reused = f", {len(summary.skipped)} unchanged and reused" if summary.skipped else ""
    print(f"graded {len(summary.graded)} student(s){reused} in {summary.seconds:.1f} s")
    for because, count in Counter(summary.reasons.values()).most_common():
        if because != "first grading":
            print(f"  {count} re-graded: {because}")
    if summary.kept:
        print(
            f"  {len(summary.kept)} graded earlier and not under {path}, kept as they were: "
            + ", ".join(one_line(k, 40) for k in summary.kept[:10])
            + (" ..." if len(summary.kept) > 10 else "")
        )
    _print_skipped(summary.ignored, summary.results)
    if summary.similarity is not None:
        print(
            f"similar answers: {len(summary.similarity.clusters)} finding(s) worth a look, "
            f"{len(summary.similarity.reference_matches)} answer(s) close to the reference "
            f"({summary.similarity_seconds:.1f} s, {summary.similarity_cpu_seconds:.1f} s of CPU, on this machine): "
            f"see the report and {out / 'similar_answers.csv'}"
        )
    elif summary.similarity_note:
        print(f"similar answers: {summary.similarity_note}")
    if args.nbgrader_db:
        from autograder.integrations.nbgrader_export import export_to_gradebook

        rows = export_to_gradebook(summary.results, args.nbgrader_db, course)
        print(f"nbgrader gradebook: {rows} exercise score(s) written to {args.nbgrader_db}")
    print(f"gradebook:    {out / 'grades.csv'}")
    print(f"class report: {out / 'report.html'}")
    print(f"feedback:     {out / 'feedback'}/<student>.html")
    print(f"Gradescope:   {out / 'results'}/<student>.json")
    return 0


def _cmd_status(args):
    from autograder.batch.class_run import Outputs, collect_results, load_saved, load_skipped, saved_student_ids
    from autograder.sandbox.launcher import LIMITS_ONLY_WARNING

    outputs = Outputs(Path(args.out))
    ids = saved_student_ids(outputs)
    roster = _read_roster(args.roster)
    results, _ = collect_results(outputs, sorted(set(ids) | set(roster)), submitted=set(ids))
    if not results:
        print(f"no results in {outputs.root}")
        return 1
    limited = [r.student_id for r in results if r.isolation == "limits"]
    if limited:
        print(
            f"WARNING: {len(limited)} of {len(results)} students were graded with resource limits only. "
            f"{LIMITS_ONLY_WARNING}\n"
        )
    _print_table(results)
    _print_lateness(results)
    because = {}
    for student_id in ids:
        saved = load_saved(outputs, student_id)
        if saved and saved.stamp.because and saved.stamp.because != "first grading":
            because[student_id] = saved.stamp.because
    if because:
        print("\nwhy the last grading of a student was a re-grade:")
        for student_id, reason in sorted(because.items()):
            print(f"  {one_line(student_id, 40)}: {one_line(reason)}")
    _print_skipped(load_skipped(outputs), results, shown=10_000)
    counts = Counter(r.status for r in results)
    print()
    print(", ".join(f"{count} {status}" for status, count in sorted(counts.items())))
    return 0


def _cmd_preview(args):
    import time

    from autograder.authoring.execute import errors, execute_notebook, save_figures
    from autograder.lessons.notebook_files import read_master

    path = Path(args.notebook)
    nb = read_master(path)
    started = time.monotonic()
    execute_notebook(nb, cwd=path.parent, allow_errors=True)
    print(f"ran {path.name} in {time.monotonic() - started:.1f} s")
    for index, cell in enumerate(nb.cells):
        for output in cell.get("outputs", []):
            if output.get("output_type") == "stream" and output.get("name") == "stderr":
                print(f"cell {index + 1} wrote to stderr: {output['text'].strip()[:400]}")
            if output.get("output_type") == "stream" and cell.source.startswith("check("):
                print(output["text"].rstrip())
    for index, ename, evalue in errors(nb):
        print(f"cell {index + 1} raised {ename}: {evalue}")
    if args.figures:
        for figure in save_figures(nb, args.figures, path.stem[:2]):
            print(f"figure: {figure}")
    return 1 if errors(nb) else 0


def _cmd_book(args):
    from autograder.authoring.book import BookFailed, build_book

    try:
        course = _course(args)
        out, pages, warnings = build_book(args.out, course.solutions, course.title)
    except BookFailed as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    if warnings.strip():
        print(f"{len(warnings.strip().splitlines())} Sphinx warning(s), see {out.parent / 'book-warnings.txt'}")
    print(f"wrote the book ({len(pages)} pages) to {out}: open {out / 'index.html'} in a browser")
    return 0


def _cmd_similarity(args):
    from autograder.similarity.report import reference_matches_by_student
    from autograder.similarity.stage import similarity_of_class, write_findings

    for folder in [args.path, *args.past]:
        if not Path(folder).is_dir():
            print(f"error: {folder} is not a folder of student submissions", file=sys.stderr)
            return 2
    findings = similarity_of_class(Path(args.path), _course(args), past=[Path(p) for p in args.past])
    csv_path, html_path = write_findings(findings, Path(args.out or args.path))
    print(
        f"compared {sum(findings.compared.values())} answers over {len(findings.compared)} exercises on this "
        "machine (nothing was sent anywhere)"
    )
    for number, cluster in enumerate(findings.clusters, 1):
        print(
            f"finding {number}, worth a look: {', '.join(one_line(m, 40) for m in cluster.members)} "
            f"on {', '.join(cluster.exercises)} (up to {100 * cluster.score:.0f}% shared)"
        )
    for student, pairs in reference_matches_by_student(findings).items():
        names = ", ".join(p.exercise for p in pairs[:5]) + (f" and {len(pairs) - 5} more" if len(pairs) > 5 else "")
        print(f"close to the reference solution: {one_line(student, 40)}, {len(pairs)} answer(s): {names}")
    for author, why in sorted(findings.unread.items()):
        print(f"not read: {one_line(author, 40)}: {one_line(why, 200)}")
    print(f"wrote {csv_path} and {html_path}")
    return 0


def _cmd_gradescope(args):
    from autograder.integrations.gradescope import build_bundle

    course = _course(args)
    path = build_bundle(
        args.out,
        course,
        lessons=_lesson_numbers(args.lessons, course),
        visibility=args.visibility,
        nbval=not args.no_nbval,
    )
    print(
        f"wrote {path} ({path.stat().st_size / 2**20:.1f} MiB): upload it as the autograder of a "
        "Gradescope programming assignment (choose the Ubuntu 24.04 base image)."
    )
    return 0


def _cmd_gradescope_run(args):
    from autograder.integrations.gradescope import run_in_container

    data = run_in_container(args.root)
    print(f"score {data['score']:g}; results written to {Path(args.root) / 'results' / 'results.json'}")
    return 0


def _cmd_nbgrader_course(args):
    from autograder.integrations.nbgrader_course import build_course

    course = _course(args)
    root = build_course(args.out, course.solutions, lessons=_lesson_numbers(args.lessons, course))
    print(
        f"wrote the nbgrader course {root}: source/lessonNN/ for each lesson, with coursekit beside it.\n"
        f"Next, with the environment active (source .venv/bin/activate): cd {root} && "
        "nbgrader generate_assignment lesson01"
    )
    return 0


def _cmd_handout(args):
    from autograder.authoring.handout import build_handout

    path = build_handout(args.out, _course(args))
    course = f" --course {args.course}" if args.course else ""
    print(
        f"wrote {path} ({path.stat().st_size / 2**20:.1f} MiB): the course notebooks, coursekit, a student "
        f"requirements.txt and a README. Run `python -m autograder release --check{course}` first."
    )
    return 0


def _cmd_course_stats(args):
    from autograder.lessons.course_stats import catalog_page, stats_markdown, stats_table

    catalog = _course(args).catalog
    text = catalog_page(catalog) if args.catalog else stats_markdown(catalog) if args.markdown else stats_table(catalog)
    print(text, end="" if text.endswith("\n") else "\n")  # --catalog's page is a whole file, newline included
    return 0


def _cmd_mutants(args):
    from autograder.mutants.run import main as run_mutants

    return run_mutants(
        _course(args),
        exercises=args.exercise or None,
        lessons=args.lessons or None,
        jobs=args.jobs,
        markdown=args.markdown,
        save=args.save,
    )


def _cmd_export(args):
    from autograder.batch.class_run import Outputs, collect_results, saved_student_ids
    from autograder.reports.roster import RosterError, read_roster

    try:
        roster = read_roster(args.roster)
    except RosterError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    catalog = _course(args).catalog
    outputs = Outputs(Path(args.out))
    ids = saved_student_ids(outputs)
    if not ids:
        print(f"error: no results in {outputs.root}", file=sys.stderr)
        return 1
    expected = sorted(set(ids) | {entry.student_id for entry in roster})
    results, _ = collect_results(outputs, expected, submitted=set(ids))
    target = Path(args.file) if args.file else outputs.root / f"{args.to}.csv"
    from autograder.batch.class_run import write_atomically

    write_atomically(target, EXPORTERS[args.to](results, catalog, roster, missing=args.missing))
    print(f"wrote {target}: {len(results)} students, {args.to} gradebook import format")
    from autograder.reports.exports.missing import not_handed_in

    absent = sum(len(not_handed_in(r, catalog.graded_lessons)) for r in results)
    if absent:
        print(
            f"  {absent} lesson(s) not handed in: "
            + (
                "exported as 0 (--missing blank leaves them empty)"
                if args.missing == "zero"
                else "left empty (--missing blank)"
            )
        )
    return 0


class _OneLineParser(argparse.ArgumentParser):
    """argparse, but a mistake on the command line is one line (what is wrong, where to look), exit status 2."""

    def error(self, message):
        self.exit(USAGE_ERROR, f"{self.prog}: error: {message} (see: {self.prog} --help)\n")


COURSE_HELP = "the course folder (default: this repository's course); see docs/AUTHORING.md"


def build_parser():
    parser = _OneLineParser(prog="python -m autograder", description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)

    new = commands.add_parser("new-course", help="write a small, working course to start your own from")
    new.add_argument("folder", help="where to write it (a new or empty folder)")
    new.set_defaults(run=_cmd_new_course)

    release = commands.add_parser("release", help="regenerate course/ from solutions/")
    release.add_argument("--check", action="store_true", help="only check that course/ is up to date")
    release.set_defaults(run=_cmd_release)

    contracts = commands.add_parser(
        "contracts", help="write each exercise's contract (coursekit/exercise_contracts.json) from its docstring"
    )
    contracts.add_argument("--check", action="store_true", help="only check that the file matches the docstrings")
    contracts.set_defaults(run=_cmd_contracts)

    record = commands.add_parser("record", help="re-record the masters' demonstration outputs")
    record.add_argument("--only", nargs="*", help="lesson prefixes such as 01 03")
    record.set_defaults(run=_cmd_record)

    grade = commands.add_parser("grade", help="grade a folder of submissions (or the sample class)")
    grade.add_argument("path", nargs="?", help="one folder per student, or nbgrader's submitted/ layout")
    grade.add_argument("--out", required=True, help="where grades.csv and feedback/ go")
    grade.add_argument("--jobs", type=_positive_jobs, default=None, help="parallel graders (default: number of cores)")
    grade.add_argument("--no-nbval", action="store_true", help="skip the notebook stage (faster)")
    grade.add_argument(
        "--lessons",
        nargs="+",
        default=(),
        metavar="NN",
        help="grade only these lessons, e.g. --lessons 01 03 (default: all)",
    )
    grade.add_argument("--roster", help="a file with one student id per line; absent ones are 'missing'")
    grade.add_argument(
        "--nbgrader-db",
        metavar="PATH",
        help="also write the scores into this nbgrader gradebook (e.g. nbgrader-course/gradebook.db)",
    )
    grade.add_argument("--force", action="store_true", help="re-grade students whose submission did not change")
    grade.add_argument(
        "--config",
        metavar="TOML",
        help="course config with due dates and the late policy (see autograder/reports/lateness.py)",
    )
    grade.add_argument(
        "--ignore-mtimes",
        action="store_true",
        help="take no hand-in time from the notebooks' modification times (a copy resets them): "
        "only nbgrader's timestamp.txt makes a lesson late",
    )
    grade.add_argument(
        "--student",
        nargs="+",
        default=(),
        metavar="ID",
        help="re-grade only these students; everyone else keeps their saved grade",
    )
    grade.add_argument(
        "--cluster",
        metavar="ADDRESS",
        help="grade on a Dask cluster: tcp://HOST:8786 (a running scheduler), or local:N "
        "(N local worker processes); see docs/CLUSTER.md",
    )
    grade.add_argument(
        "--layout",
        choices=("folders", "nbgrader"),
        default=None,
        help="how the class is laid out: one folder per student, or nbgrader's submitted/<student>/<assignment>/ "
        "(default: nbgrader's only for its course root, nbgrader_config.py or gradebook.db beside submitted/)",
    )
    grade.add_argument(
        "--share-output",
        action="store_true",
        help="let group and others read the output folder (grades, feedback pages); by default only you can",
    )
    grade.add_argument(
        "--no-similarity",
        action="store_true",
        help="do not compare the students' answers with each other (the 'Similar answers' section)",
    )
    grade.set_defaults(run=_cmd_grade)

    similar = commands.add_parser(
        "similarity",
        help="compare a class's answers with each other, the reference solution and past terms (on this machine)",
    )
    similar.add_argument("path", help="one folder per student, or nbgrader's submitted/ layout")
    similar.add_argument("--out", default=None, help="where similar_answers.csv and .html go (default: PATH)")
    similar.add_argument("--past", nargs="+", default=(), metavar="DIR", help="past terms' submissions")
    similar.set_defaults(run=_cmd_similarity)

    canary = commands.add_parser("canary", help="grade the reference solutions: does every stage work here?")
    canary.add_argument("--lessons", nargs="+", default=(), metavar="NN", help="only these lessons")
    canary.add_argument("--no-nbval", action="store_true", help="skip the notebook stage")
    canary.set_defaults(run=_cmd_canary)

    course = commands.add_parser("nbgrader-course", help="write an nbgrader course (source/lessonNN/) from solutions/")
    course.add_argument("--out", required=True, help="the course root to create or update")
    course.add_argument("--lessons", nargs="+", default=(), metavar="NN", help="only these lessons")
    course.set_defaults(run=_cmd_nbgrader_course)

    handout = commands.add_parser("handout", help="pack the students' hand-out (notebooks, coursekit, install list)")
    handout.add_argument("--out", required=True, help="the zip to write, e.g. course.zip")
    handout.set_defaults(run=_cmd_handout)

    export = commands.add_parser("export", help="write the saved grades in a learning-management system's format")
    export.add_argument("--out", required=True, help="the results folder of `grade`")
    export.add_argument("--to", required=True, choices=sorted(EXPORTERS), help="the format")
    export.add_argument("--roster", help="CSV roster with names, sections, SIS ids (see autograder/reports/roster.py)")
    export.add_argument("--file", help="where to write (default: OUT/<format>.csv)")
    export.add_argument(
        "--missing",
        choices=("zero", "blank"),
        default="zero",
        help="a lesson not handed in: 0 points (default) or an empty cell",
    )
    export.set_defaults(run=_cmd_export)

    status = commands.add_parser("status", help="show the saved results of a grading run")
    status.add_argument("--out", required=True)
    status.add_argument("--roster", help="a file with one student id per line; absent ones are 'missing'")
    status.set_defaults(run=_cmd_status)

    gradescope = commands.add_parser("gradescope", help="build a Gradescope autograder bundle (zip)")
    gradescope.add_argument("--out", required=True, help="the zip to write, e.g. autograder.zip")
    gradescope.add_argument("--lessons", nargs="+", default=(), metavar="NN", help="lessons it grades (default all)")
    gradescope.add_argument(
        "--visibility",
        default="after_due_date",
        choices=["hidden", "after_due_date", "after_published", "visible"],
        help="when students see each check's details (default: after the due date)",
    )
    gradescope.add_argument("--no-nbval", action="store_true", help="skip the notebook stage")
    gradescope.set_defaults(run=_cmd_gradescope)

    run = commands.add_parser("gradescope-run", help="(inside Gradescope) grade ROOT/submission")
    run.add_argument("--root", default="/autograder")
    run.set_defaults(run=_cmd_gradescope_run)

    preview = commands.add_parser("preview", help="run a notebook and save its figures (for authors)")
    preview.add_argument("notebook")
    preview.add_argument("--figures", help="folder for the PNG files")
    preview.set_defaults(run=_cmd_preview)

    mutants = commands.add_parser(
        "mutants", help="mutation-test the hidden suite and the public checks on mutants of the reference answers"
    )
    mutants.add_argument("--exercise", nargs="*", default=[], help="only these exercises")
    mutants.add_argument("--lessons", nargs="*", default=[], help="only these lessons, e.g. 03 04")
    mutants.add_argument("--jobs", type=_positive_jobs, default=None, help="processes (default: 2, or 1 on one core)")
    mutants.add_argument("--markdown", action="store_true", help="print the table as Markdown (for the README)")
    mutants.add_argument("--save", metavar="FILE.json", help="also write every mutant's outcome and source as JSON")
    mutants.set_defaults(run=_cmd_mutants)

    book = commands.add_parser("book", help="build the solved lessons as a static website (open OUT/index.html)")
    book.add_argument("--out", default="_build/book", help="the folder to write (replaced), e.g. _build/book")
    book.set_defaults(run=_cmd_book)

    stats = commands.add_parser(
        "course-stats", help="what the exercises ask for: kinds, points and minutes per lesson (issue 42's targets)"
    )
    form = stats.add_mutually_exclusive_group()
    form.add_argument("--markdown", action="store_true", help="print the table as Markdown")
    form.add_argument(
        "--catalog", action="store_true", help="print the catalog of every exercise (docs/EXERCISES.md) as Markdown"
    )
    stats.set_defaults(run=_cmd_course_stats)
    for command in (
        release,
        contracts,
        record,
        grade,
        similar,
        canary,
        course,
        handout,
        export,
        gradescope,
        mutants,
        book,
        stats,
    ):
        command.add_argument("--course", metavar="DIR", default=None, help=COURSE_HELP)
    return parser


def _interrupted_line(args):
    """What Ctrl-C leaves behind, and how to go on."""
    if args.command == "grade":
        return (
            f"interrupted: every student graded so far is saved in {Path(args.out) / 'students'}; run the same "
            "command again to resume (saved students are not graded twice)"
        )
    return f"interrupted: `{args.command}` stopped before it finished; run it again"


def main(argv=None):
    import signal

    args = build_parser().parse_args(argv)
    interrupted = []

    def on_ctrl_c(signum, frame):  # remembered, as a library on the way (pytest) may turn it into its own error
        interrupted.append(signum)
        raise KeyboardInterrupt

    signal.signal(signal.SIGINT, on_ctrl_c)
    try:
        status = args.run(args)
        sys.stdout.flush()  # here, so that a closed pipe is met inside this try and not at exit
        return status
    except UsageError as error:
        print(f"error: {error}", file=sys.stderr)
        return USAGE_ERROR
    except BrokenPipeError:  # `status | head`: the reader has all it wanted; say nothing more, anywhere
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return CLOSED_PIPE
    except BaseException:
        if not interrupted:
            raise
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # a second Ctrl-C must not cut the one line short
        print(f"\n{_interrupted_line(args)}", file=sys.stderr, flush=True)
        sys.stdout.flush()
        # Ended here: Python would die of SIGINT at exit (status -2, after our line) when a library on the way let
        # the interrupt pass through code it ran; a killed run's temporary files are swept by the next one.
        os._exit(INTERRUPTED)
