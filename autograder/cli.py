"""``python -m autograder``: release the course, record outputs, grade a class.

Commands
--------
release [--check]
    Regenerate ``course/`` from ``solutions/``; ``--check`` only verifies.
record [--only NN ...]
    Re-record the demonstration outputs stored in the masters.
grade [PATH] --out DIR [--jobs N] [--no-nbval] [--lessons NN ...] [--roster FILE]
      [--nbgrader-db PATH] [--force] [--student ID ...] [--config course.toml] [--cluster ADDRESS]
    Grade every student folder in PATH (or the bundled sample class); with
    --student, re-grade only those. The gradebook never loses a student.
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
book --out DIR
    Build the book: the solved lessons, executed, as a static website
    (open DIR/index.html in a browser; no Python needed to read it).
"""

import argparse
import sys
from collections import Counter
from pathlib import Path

from autograder.lessons.untrusted_text import one_line
from autograder.reports.exports import EXPORTERS


def _cmd_release(args):
    from autograder.authoring.release import release, stale_files

    if args.check:
        problems = stale_files()
        for path, reason in problems:
            print(f"{path}: {reason}")
        if problems:
            print(f"course/ is out of date: {len(problems)} file(s). Run: python -m autograder release")
            return 1
        print("course/ and solutions/ are in sync.")
        return 0
    written = release()
    for path in written:
        print(f"wrote {path}")
    print(f"release done: {len(written)} file(s) changed.")
    return 0


def _cmd_record(args):
    from autograder.authoring.record import RecordingFailed, record_outputs

    try:
        changed = record_outputs(only=args.only)
    except RecordingFailed as error:
        print(f"record failed: {error}", file=sys.stderr)
        return 1
    for path in changed:
        print(f"recorded {path}")
    print(f"record done: {len(changed)} master(s) changed. Run `python -m autograder release` next.")
    return 0


def _print_table(results, problems_shown=3):
    """The gradebook as a table; under a student graded with problems, the problems themselves.
    Student text is shown escaped, one line each, bounded (autograder/lessons/untrusted_text.py)."""
    ids = [one_line(r.student_id, 40) for r in results]
    width = max([len("student")] + [len(i) for i in ids])
    print(f"{'student':<{width}}  {'score':>13}  status")
    for shown_id, r in zip(ids, results):
        score = f"{r.score:g} / {r.max_score:g}" if r.max_score else "—"
        status = one_line(r.status + (f": {r.reason}" if r.reason else ""))
        print(f"{shown_id:<{width}}  {score:>13}  {status}")
        for problem in r.problems[:problems_shown]:
            print(f"{'':<{width}}  {'':>13}    - {one_line(problem, 160)}")
        if len(r.problems) > problems_shown:
            print(f"{'':<{width}}  {'':>13}    - and {len(r.problems) - problems_shown} more "
                  "(see the student's feedback page)")


def _print_skipped(ignored, results, shown=20):
    """What was not graded: entries of the submissions folder (``ignored``) and, per student, what the
    walk of their folder skipped; at most ``shown`` lines of each (``status`` lists them all)."""
    inside = [r for r in results if r.skipped]
    sections = [
        (f"not graded: {len(ignored)} entr{'y' if len(ignored) == 1 else 'ies'} of the submissions folder that are "
         "not student folders:", [one_line(item.line(), 200) for item in ignored]),
        (f"not read: {len(inside)} student folder(s) hold entries the grader skipped (hidden, links, too deep):",
         [f"{one_line(r.student_id, 40)}: {one_line('; '.join(r.skipped), 200)}" for r in inside])]
    if ignored or inside:
        print()
    for title, lines in sections:
        if lines:
            print(title)
            for line in lines[:shown]:
                print(f"  {line}")
            if len(lines) > shown:
                print(f"  and {len(lines) - shown} more (`status` lists them all)")


def _read_roster(path):
    """Roster ids from ``path`` (plain ids or a CSV; see autograder/reports/roster.py)."""
    from autograder.reports.roster import read_roster

    return tuple(entry.student_id for entry in read_roster(path))


def _cmd_canary(args):
    from autograder.batch.class_run import _prewarm
    from autograder.grading.canary import CanaryFailed, describe_canary, ensure_reference_passes
    from autograder.grading.fingerprint import fingerprint_parts
    from autograder.grading.pipeline import GradingOptions
    from autograder.sandbox import launcher

    print(launcher.describe_isolation())
    options = GradingOptions(nbval=not args.no_nbval, lessons=tuple(args.lessons))
    _prewarm()
    try:
        print(describe_canary(ensure_reference_passes(options, fingerprint_parts(options))))
    except CanaryFailed as error:
        print(f"error: canary failed: {error}", file=sys.stderr)
        return 3
    return 0


def _cmd_grade(args):
    from autograder.batch.class_run import UnknownStudents, grade_class
    from autograder.batch.progress import Progress
    from autograder.grading.canary import CanaryFailed
    from autograder.grading.pipeline import GradingOptions
    from autograder.integrations.cluster import ClusterError
    from autograder.reports.lateness import ConfigError, load_config
    from autograder.sandbox import launcher, warm

    out = Path(args.out)
    path = args.path
    if path is None:
        from autograder.authoring.sample_class import build_sample_class

        path = out / "sample_class"
        build_sample_class(path, lessons=tuple(args.lessons))
        print(f"No PATH given: grading the bundled sample class, written to {path}")
    path = Path(path)
    if not path.is_dir():
        print(f"error: {path} is not a folder of student submissions", file=sys.stderr)
        return 2
    print(launcher.describe_isolation())
    if not args.cluster and warm.enabled():
        print("sandbox slots: each grading process keeps one warm sandbox whose workers are forked fresh for "
              "every student and reset between students (SECURITY.md, \"Warm slots\"; AUTOGRADER_WARM=0 turns "
              "them off)")
    options = GradingOptions(nbval=not args.no_nbval, lessons=tuple(args.lessons))
    try:
        config = load_config(args.config) if args.config else None
    except ConfigError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    runner = None
    if args.cluster:  # students become Dask tasks (autograder/integrations/cluster.py, docs/CLUSTER.md)
        from autograder.integrations.cluster import connect

        try:
            runner = connect(args.cluster, options, announce=lambda line: print(line, flush=True))
        except ClusterError as error:
            print(f"error: {error}", file=sys.stderr)
            return 2
    try:
        summary = grade_class(path, out, jobs=args.jobs, options=options, force=args.force,
                              progress=Progress(sys.stderr), roster=_read_roster(args.roster),
                              only=tuple(args.student), announce=lambda line: print(line, flush=True),
                              config=config, runner=runner)
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
    print()
    reused = f", {len(summary.skipped)} unchanged and reused" if summary.skipped else ""
    print(f"graded {len(summary.graded)} student(s){reused} in {summary.seconds:.1f} s")
    for because, count in Counter(summary.reasons.values()).most_common():
        if because != "first grading":
            print(f"  {count} re-graded: {because}")
    if summary.kept:
        print(f"  {len(summary.kept)} graded earlier and not under {path}, kept as they were: "
              + ", ".join(one_line(k, 40) for k in summary.kept[:10]) + (" ..." if len(summary.kept) > 10 else ""))
    _print_skipped(summary.ignored, summary.results)
    if args.nbgrader_db:
        from autograder.integrations.nbgrader_export import export_to_gradebook

        rows = export_to_gradebook(summary.results, args.nbgrader_db)
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
        print(f"WARNING: {len(limited)} of {len(results)} students were graded with resource limits only. "
              f"{LIMITS_ONLY_WARNING}\n")
    _print_table(results)
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
        out, pages, warnings = build_book(args.out)
    except BookFailed as error:
        print(f"error: {error}", file=sys.stderr)
        return 1
    if warnings.strip():
        print(f"{len(warnings.strip().splitlines())} Sphinx warning(s), see {out.parent / 'book-warnings.txt'}")
    print(f"wrote the book ({len(pages)} pages) to {out}: open {out / 'index.html'} in a browser")
    return 0


def _cmd_gradescope(args):
    from autograder.integrations.gradescope import build_bundle

    path = build_bundle(args.out, lessons=tuple(args.lessons), visibility=args.visibility, nbval=not args.no_nbval)
    print(f"wrote {path} ({path.stat().st_size / 2**20:.1f} MiB): upload it as the autograder of a "
          "Gradescope programming assignment (choose the Ubuntu 24.04 base image).")
    return 0


def _cmd_gradescope_run(args):
    from autograder.integrations.gradescope import run_in_container

    data = run_in_container(args.root)
    print(f"score {data['score']:g}; results written to {Path(args.root) / 'results' / 'results.json'}")
    return 0


def _cmd_nbgrader_course(args):
    from autograder.integrations.nbgrader_course import build_course

    root = build_course(args.out, lessons=tuple(args.lessons))
    print(f"wrote the nbgrader course {root}: source/lessonNN/ for each lesson, with coursekit beside it.\n"
          f"Next, with the environment active (source .venv/bin/activate): cd {root} && "
          "nbgrader generate_assignment lesson01")
    return 0


def _cmd_handout(args):
    from autograder.authoring.handout import build_handout

    path = build_handout(args.out)
    print(f"wrote {path} ({path.stat().st_size / 2**20:.1f} MiB): the course notebooks, coursekit, a student "
          "requirements.txt and a README. Run `python -m autograder release --check` first.")
    return 0


def _cmd_mutants(args):
    from autograder.mutants.run import main as run_mutants

    return run_mutants(exercises=args.exercise or None, lessons=args.lessons or None, jobs=args.jobs,
                       markdown=args.markdown, save=args.save)


def _cmd_export(args):
    from autograder.batch.class_run import Outputs, collect_results, saved_student_ids
    from autograder.lessons.catalog import load_catalog
    from autograder.reports.roster import RosterError, read_roster

    try:
        roster = read_roster(args.roster)
    except RosterError as error:
        print(f"error: {error}", file=sys.stderr)
        return 2
    outputs = Outputs(Path(args.out))
    ids = saved_student_ids(outputs)
    if not ids:
        print(f"error: no results in {outputs.root}", file=sys.stderr)
        return 1
    expected = sorted(set(ids) | {entry.student_id for entry in roster})
    results, _ = collect_results(outputs, expected, submitted=set(ids))
    target = Path(args.file) if args.file else outputs.root / f"{args.to}.csv"
    from autograder.batch.class_run import write_atomically

    write_atomically(target, EXPORTERS[args.to](results, load_catalog(), roster))
    print(f"wrote {target}: {len(results)} students, {args.to} gradebook import format")
    return 0


def build_parser():
    parser = argparse.ArgumentParser(prog="python -m autograder", description=__doc__.split("\n")[0])
    commands = parser.add_subparsers(dest="command", required=True)

    release = commands.add_parser("release", help="regenerate course/ from solutions/")
    release.add_argument("--check", action="store_true", help="only check that course/ is up to date")
    release.set_defaults(run=_cmd_release)

    record = commands.add_parser("record", help="re-record the masters' demonstration outputs")
    record.add_argument("--only", nargs="*", help="lesson prefixes such as 01 03")
    record.set_defaults(run=_cmd_record)

    grade = commands.add_parser("grade", help="grade a folder of submissions (or the sample class)")
    grade.add_argument("path", nargs="?", help="one folder per student, or nbgrader's submitted/ layout")
    grade.add_argument("--out", required=True, help="where grades.csv and feedback/ go")
    grade.add_argument("--jobs", type=int, default=None, help="parallel graders (default: number of cores)")
    grade.add_argument("--no-nbval", action="store_true", help="skip the notebook stage (faster)")
    grade.add_argument("--lessons", nargs="+", default=(), metavar="NN",
                       help="grade only these lessons, e.g. --lessons 01 03 (default: all)")
    grade.add_argument("--roster", help="a file with one student id per line; absent ones are 'missing'")
    grade.add_argument("--nbgrader-db", metavar="PATH",
                       help="also write the scores into this nbgrader gradebook (e.g. nbgrader-course/gradebook.db)")
    grade.add_argument("--force", action="store_true", help="re-grade students whose submission did not change")
    grade.add_argument("--config", metavar="TOML",
                       help="course config with due dates and the late policy (see autograder/reports/lateness.py)")
    grade.add_argument("--student", nargs="+", default=(), metavar="ID",
                       help="re-grade only these students; everyone else keeps their saved grade")
    grade.add_argument("--cluster", metavar="ADDRESS",
                       help="grade on a Dask cluster: tcp://HOST:8786 (a running scheduler), or local:N "
                            "(N local worker processes); see docs/CLUSTER.md")
    grade.set_defaults(run=_cmd_grade)

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
    export.set_defaults(run=_cmd_export)

    status = commands.add_parser("status", help="show the saved results of a grading run")
    status.add_argument("--out", required=True)
    status.add_argument("--roster", help="a file with one student id per line; absent ones are 'missing'")
    status.set_defaults(run=_cmd_status)

    gradescope = commands.add_parser("gradescope", help="build a Gradescope autograder bundle (zip)")
    gradescope.add_argument("--out", required=True, help="the zip to write, e.g. autograder.zip")
    gradescope.add_argument("--lessons", nargs="+", default=(), metavar="NN", help="lessons it grades (default all)")
    gradescope.add_argument("--visibility", default="after_due_date",
                            choices=["hidden", "after_due_date", "after_published", "visible"],
                            help="when students see each check's details (default: after the due date)")
    gradescope.add_argument("--no-nbval", action="store_true", help="skip the notebook stage")
    gradescope.set_defaults(run=_cmd_gradescope)

    run = commands.add_parser("gradescope-run", help="(inside Gradescope) grade ROOT/submission")
    run.add_argument("--root", default="/autograder")
    run.set_defaults(run=_cmd_gradescope_run)

    preview = commands.add_parser("preview", help="run a notebook and save its figures (for authors)")
    preview.add_argument("notebook")
    preview.add_argument("--figures", help="folder for the PNG files")
    preview.set_defaults(run=_cmd_preview)

    mutants = commands.add_parser("mutants", help="mutation-test the hidden suite and the public checks "
                                                  "on mutants of the reference answers")
    mutants.add_argument("--exercise", nargs="*", default=[], help="only these exercises")
    mutants.add_argument("--lessons", nargs="*", default=[], help="only these lessons, e.g. 03 04")
    mutants.add_argument("--jobs", type=int, default=None, help="processes (default: 2, or 1 on one core)")
    mutants.add_argument("--markdown", action="store_true", help="print the table as Markdown (for the README)")
    mutants.add_argument("--save", metavar="FILE.json", help="also write every mutant's outcome and source as JSON")
    mutants.set_defaults(run=_cmd_mutants)

    book = commands.add_parser("book", help="build the solved lessons as a static website (open OUT/index.html)")
    book.add_argument("--out", default="_build/book", help="the folder to write (replaced), e.g. _build/book")
    book.set_defaults(run=_cmd_book)
    return parser


def main(argv=None):
    args = build_parser().parse_args(argv)
    return args.run(args)
