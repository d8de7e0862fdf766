"""Accessibility of what readers, students and instructors open in a browser: the book, a feedback page
and the class report.

axe-core (bundled by ``axe-playwright-python``) runs in headless Chromium on
every page of one shared book build (``book_build.shared_book``), on a feedback
page and on the class report: no violation of impact "serious" or "critical"
(colour contrast on two book pages: see CONTRAST_LESSON).
Every figure of the book has its caption as alt text, never its file path, and
lesson 03's Figure 3 tells its two series apart by more than colour.
Screenshots of the pages are kept in test-artifacts/accessibility/ (the path is printed).
"""

import re

import matplotlib
import pytest
from bs4 import BeautifulSoup

matplotlib.use("agg")
import matplotlib.pyplot as plt  # noqa: E402
import nbformat  # noqa: E402
import numpy as np  # noqa: E402

from autograder.grading.results import CheckResult, ExerciseResult, LessonResult, NotebookRun, StudentResult  # noqa: E402,E501
from autograder.lessons.paths import PROJECT_ROOT, SOLUTIONS  # noqa: E402
from autograder.reports.class_report import class_report_html  # noqa: E402
from autograder.reports.feedback import feedback_html  # noqa: E402
from book_build import shared_book  # noqa: E402
from browser_support import Browser, open_book_page, require_chromium  # noqa: E402
from support import THIS_COURSE

LESSONS = sorted(p.stem for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb"))
BLOCKING = ("serious", "critical")


@pytest.fixture(scope="module")
def book(tmp_path_factory, request):
    return shared_book(tmp_path_factory, getattr(request.config, "workerinput", None))


@pytest.fixture(scope="module")
def screenshots():
    """test-artifacts/accessibility/ (ignored by git, kept after the run, unlike pytest's temporary folders)."""
    folder = PROJECT_ROOT / "test-artifacts" / "accessibility"
    folder.mkdir(parents=True, exist_ok=True)
    print(f"\naccessibility screenshots: {folder}")
    return folder


@pytest.fixture(scope="module")
def browser():
    sync_api = require_chromium()
    pytest.importorskip("axe_playwright_python", reason="pip install -r environment.txt (axe-playwright-python)")
    opened = Browser(sync_api)
    yield opened
    opened.close()


# Colour contrast is most of axe's time on a lesson page (thousands of MathJax nodes: about 14 s of 19 on a
# loaded machine). Every page shares the theme's and the outputs' colours, so it runs on the front page and on
# CONTRAST_LESSON (the one with the most kinds of output); every other rule runs on every page.
CONTRAST_LESSON = "03_exp_and_log"
WITHOUT_CONTRAST = {"resultTypes": ["violations"], "rules": {"color-contrast": {"enabled": False}}}


def _blocking_violations(page, contrast=True):
    """axe-core's serious and critical violations on the open page, one line each."""
    from axe_playwright_python.sync_playwright import Axe

    options = {"resultTypes": ["violations"]} if contrast else WITHOUT_CONTRAST
    violations = Axe().run(page, options=options).response["violations"]
    return [
        f"{v['impact']} {v['id']}: {v['help']} ({len(v['nodes'])}x, e.g. {v['nodes'][0]['target']})"
        for v in violations
        if v.get("impact") in BLOCKING
    ]


def _student(student_id, failing):
    """A graded student of lesson 01 whose ``failing`` exercises lost their points, with a hint each."""
    exercises = []
    for exercise in THIS_COURSE.catalog.lesson("01").exercises:
        lost = exercise.name in failing
        check = CheckResult(
            exercise=exercise.name,
            description=f"{exercise.name} on random rotations",
            weight=1.0,
            passed=not lost,
            reason="off by 0.5 at θ = 1.2" if lost else "",
            hint="looks like the transpose" if lost else "",
        )
        exercises.append(
            ExerciseResult(
                name=exercise.name,
                lesson="01",
                max_points=exercise.points,
                points=0.0 if lost else exercise.points,
                checks=[check],
            )
        )
    lesson = LessonResult(
        number="01",
        title=THIS_COURSE.catalog.lesson("01").title,
        notebook="01_frames_and_rotations.ipynb",
        status="graded",
        exercises=exercises,
        run=NotebookRun(status="passed", points=1.0, max_points=1.0),
    )
    return StudentResult(student_id=student_id, status="graded", lessons=[lesson])


def _open(browser, path):
    page = browser.page()
    page.goto(path.as_uri())
    page.wait_for_load_state("load")
    return page


def test_book_pages_have_no_serious_violations(book, browser, screenshots):
    found = {}
    for name in ["index"] + LESSONS[1:]:
        page = browser.page()
        open_book_page(page, book / f"{name}.html")
        page.screenshot(path=str(screenshots / f"book_{name[:2]}.png"))
        problems = _blocking_violations(page, contrast=name in ("index", CONTRAST_LESSON))
        if problems:
            found[name] = problems
        page.close()
    assert not found, found


def test_feedback_page_and_class_report_have_no_serious_violations(browser, screenshots, tmp_path):
    students = [
        _student("ana", failing=()),
        _student("dev", failing=("rot_z", "rotate_point")),
        StudentResult(student_id="ed", status="missing", reason="no submission folder"),
    ]
    pages = {"feedback": feedback_html(students[1]), "class_report": class_report_html(students, THIS_COURSE.catalog)}
    found = {}
    for name, html in pages.items():
        path = tmp_path / f"{name}.html"
        path.write_text(html, encoding="utf-8")
        page = _open(browser, path)
        page.screenshot(path=str(screenshots / f"{name}.png"), full_page=True)
        problems = _blocking_violations(page)
        if problems:
            found[name] = problems
        page.close()
    assert not found, found


def test_every_book_figure_has_its_caption_as_alt_text(book):
    missing = []
    for name in ["index"] + LESSONS[1:]:
        soup = BeautifulSoup((book / f"{name}.html").read_text(encoding="utf-8"), "html.parser")
        for img in (soup.find("article") or soup).find_all("img"):
            alt = img.get("alt", "")
            if not re.match(r"Figure \d+[a-z]?\. \S", alt) or "_images/" in alt or alt.endswith(".png"):
                missing.append(f"{name}: {img.get('src')} alt={alt[:60]!r}")
    assert not missing, missing


def _labelled_series(ax):
    return [line for line in ax.get_lines() if not line.get_label().startswith("_")]


def test_lesson_03_figure_3_tells_its_series_apart_without_colour(monkeypatch):
    """Each labelled series of the log-accuracy figure differs from the others in marker or line style,
    and a legend names them."""
    master = nbformat.read(str(SOLUTIONS / "03_exp_and_log.ipynb"), as_version=4)
    (cell,) = [c for c in master.cells if c.cell_type == "code" and "Figure 3." in c.source]
    reference = THIS_COURSE.reference
    namespace = {"np": np, "plt": plt, "log_so3": reference.log_so3, "vee": reference.vee}
    from coursekit.lie import Exp

    namespace["Exp"] = Exp
    monkeypatch.setattr(plt, "show", lambda *args, **kwargs: None)
    plt.close("all")
    exec(compile(cell.source, "lesson 03, Figure 3", "exec"), namespace)
    fig = plt.gcf()
    assert any(ax.get_legend() is not None for ax in fig.axes), "no legend names the series"
    for ax in fig.axes:
        styles = [
            (line.get_marker(), line.get_linestyle(), line.get_markerfacecolor() == "none")
            for line in _labelled_series(ax)
        ]
        assert len(styles) >= 2 and len(set(styles)) == len(styles), styles
    plt.close(fig)
