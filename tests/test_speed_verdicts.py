"""Speed work never moves a verdict.

- The sample class graded now gets exactly the points of the recorded golden
  gradebook (``tests/golden/sample_class_grades.csv``, recorded by
  ``python -m tests.record_golden``): every exercise, every notebook point.
  That check is in ``tests/test_sample_class.py``, on the class it grades anyway.
- So does the benchmark's class (``support.benchmark_class``, 8 students:
  reference answers, stubs and mixed typical mistakes), against
  ``tests/golden/benchmark_class_grades.csv``.
- nbval runs only where it can change the grade: a lesson that lost hidden
  points gets a ``skipped`` run worth 0 that says why, and never reaches nbval.
- The class report counts the notebooks that ran and those that were not run.
"""

from autograder.grading import nbval_stage, pipeline as grading
from autograder.grading.results import ExerciseResult, LessonResult, NotebookRun, StudentResult
from autograder.reports.class_report import class_report_html
from support import STUB, build_submission
from support import THIS_COURSE


def _lesson(points):
    shell = LessonResult(number="01", title="t", notebook="01.ipynb", status="graded")
    shell.exercises = [
        ExerciseResult(name=f"e{i}", lesson="01", max_points=2.0, points=p) for i, p in enumerate(points)
    ]
    return shell


def test_a_lesson_that_lost_hidden_points_is_not_run_and_says_why():
    shell = _lesson([2.0, 1.5])
    assert not nbval_stage.full_hidden_marks(shell)
    shell.run = nbval_stage.not_run_for_lost_points(1.0)
    nbval_stage.award(shell)
    assert (shell.run.status, shell.run.points, shell.run.max_points) == ("skipped", 0.0, 1.0)
    assert shell.run.failures == ["not run: the point needs every exercise of the lesson to pass its hidden checks"]


def test_award_is_unchanged_for_lessons_that_ran():
    passed = _lesson([2.0, 2.0])
    passed.run = NotebookRun(status="passed", max_points=1.0)
    nbval_stage.award(passed)
    assert passed.run.points == 1.0
    failed = _lesson([2.0, 2.0])
    failed.run = NotebookRun(status="failed", max_points=1.0, failures=["the cell `x` raised"])
    nbval_stage.award(failed)
    assert failed.run.points == 0.0 and failed.run.failures == ["the cell `x` raised"]
    partial = _lesson([2.0, 1.0])
    partial.run = NotebookRun(status="passed", max_points=1.0)
    nbval_stage.award(partial)
    assert partial.run.points == 0.0
    assert partial.run.failures == [
        "the notebook ran, but the point needs every exercise of the lesson to pass its hidden checks"
    ]


def test_nbval_gets_only_the_lessons_with_full_hidden_marks(tmp_path, monkeypatch):
    """Lesson 01 answered, lesson 02 left as stubs: nbval is asked for 01 only; 02 is skipped, worth 0."""
    catalog = THIS_COURSE.catalog
    first, second = catalog.graded_lessons[0], catalog.graded_lessons[1]
    folder = tmp_path / "student"
    build_submission(
        folder, {exercise.name: STUB for exercise in second.exercises}, lessons=[first.number, second.number]
    )
    asked = []

    def fake_run_notebooks(folder, lessons, options, catalog, slot=None):
        asked.extend(shell.number for shell, _, _ in lessons)
        return {
            shell.number: NotebookRun(status="passed", max_points=options.notebook_points) for shell, _, _ in lessons
        }

    monkeypatch.setattr(grading, "run_notebooks", fake_run_notebooks)
    result = grading.grade_student(
        "s", folder, grading.GradingContext(THIS_COURSE, grading.GradingOptions(lessons=(first.number, second.number)))
    )
    runs = {lesson.number: lesson.run for lesson in result.lessons}
    assert asked == [first.number]
    assert (runs[first.number].status, runs[first.number].points) == ("passed", 1.0)
    assert (runs[second.number].status, runs[second.number].points) == ("skipped", 0.0)
    assert "not run" in runs[second.number].failures[0]


def test_class_report_counts_notebooks_run_and_not_run():
    def student(status):
        lesson = _lesson([2.0])
        lesson.run = NotebookRun(status=status, max_points=1.0)
        return StudentResult(student_id=status, status="graded", lessons=[lesson])

    html = class_report_html([student("passed"), student("failed"), student("skipped")], THIS_COURSE.catalog)
    row = html[html.index("Notebook stage") :]
    assert '<tr><td>01</td><td class="num">1 / 2</td><td class="num">2</td><td class="num">1</td></tr>' in row


def test_the_benchmark_class_keeps_its_golden_verdicts(tmp_path):
    import record_golden

    graded = record_golden.verdicts(record_golden.grade_benchmark_class(tmp_path))
    changed = record_golden.differences(record_golden.read_golden(record_golden.BENCHMARK_GOLDEN), graded)
    assert not changed, (
        "verdicts moved on the benchmark's class:\n"
        + "\n".join(changed[:30])
        + "\n(re-record with `python -m tests.record_golden` only if the change is intended)"
    )
