"""The course as students and readers meet it: JupyterLab in a real browser.

One JupyterLab (this environment, default settings, loopback) serves copies
of course/ and solutions/; headless Chromium (Debian's ``chromium`` through
Playwright) opens each lesson, runs all cells from the Run menu, and checks
what a person sees with ``browser_support.page_problems``: no raw TeX, no
MathJax error, no JavaScript error, every image and figure canvas drawn, and
(in the solved lessons) nothing on stderr, every live figure named by its
caption for a screen reader (no TeX in the name), and nothing under a clean
"Ready to hand in?". A student's typed answer turns a check from ✗ to ✓; a
worked example run ahead of its exercise ends in one line; a slider of an
explorer changes its figure, and the figure's title says the slider's value.
Last, a copy of a lesson is broken three ways and the same check must report
each. Screenshots go to ``test-artifacts/browser/``.
"""

import json
import re
import shutil
import subprocess
import sys
import time
import zipfile

import nbformat
import pytest

from autograder.authoring.handout import build_handout
from autograder.lessons.paths import COURSE, PROJECT_ROOT, SOLUTIONS
from browser_support import (
    LAB_SELECTORS,
    Browser,
    JupyterLab,
    changed_figures,
    figure_pictures,
    open_and_run_all,
    page_problems,
    require_chromium,
)
from support import THIS_COURSE

ARTIFACTS = PROJECT_ROOT / "test-artifacts" / "browser"
LESSONS = sorted(p.name for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb"))
TIMINGS = {}
PICTURES = {}  # the figures of each solved lesson as drawn in the browser, the reference for the breakage test


@pytest.fixture(scope="module")
def session(tmp_path_factory):
    sync_api = require_chromium()
    root = tmp_path_factory.mktemp("lab")
    for folder in (COURSE, SOLUTIONS):
        shutil.copytree(folder, root / folder.name, ignore=shutil.ignore_patterns("__pycache__"))
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    lab = JupyterLab(root)
    browser = Browser(sync_api)
    yield {"lab": lab, "browser": browser, "root": root}
    browser.close()
    lab.stop()
    for name, seconds in TIMINGS.items():
        print(f"browser: {name} {seconds:.1f} s")


def _run(session, relative):
    page = session["browser"].page()
    started = time.monotonic()
    open_and_run_all(session["lab"], page, relative)
    TIMINGS[relative] = time.monotonic() - started
    return page


def test_the_handout_notebooks_open_unmodified(session):
    """Opening a lesson of the hand-out, installed as its README says, marks nothing modified.

    JupyterLab writes the kernel's ``language_info`` (with its Python's version) into the notebook
    when the kernel starts, which marks the tab modified unless it is already there word for word:
    no hand-out can match students on Pythons 3.10 to 3.14, so the install line's ``check_python.py``
    writes the student's own (run here with the kernel's Python). The tab must be clean once the
    kernel is idle; then it is saved, and anything else that changed on opening (cell ids, the
    format's version, widget state, a cell's source) is a modification the student did not make.
    """
    folder = session["root"] / "handout"
    with zipfile.ZipFile(build_handout(session["root"] / "course.zip", THIS_COURSE)) as archive:
        archive.extractall(folder)
    subprocess.run([sys.executable, str(folder / "rotations-course" / "check_python.py")], check=True, timeout=60)
    page = session["browser"].page()
    changed, dirty = {}, []
    for name in LESSONS:
        path = folder / "rotations-course" / name
        before = json.loads(path.read_text(encoding="utf-8"))
        page.goto(session["lab"].url(f"handout/rotations-course/{name}"))
        page.wait_for_selector(".jp-NotebookPanel .jp-Cell", timeout=90_000)
        page.wait_for_function("() => document.body.innerText.includes('Idle')", timeout=90_000)
        page.wait_for_timeout(1500)  # widgets and the kernel's info arrive right after it starts
        if page.query_selector(".lm-TabBar-tab.jp-mod-current.jp-mod-dirty"):
            dirty.append(name)
        # the save's own answer, not the tab's dot (already clean), says the file is written
        with page.expect_response(
            lambda response: "/api/contents/" in response.url and response.request.method == "PUT", timeout=30_000
        ):
            page.keyboard.press("Control+s")
        after = json.loads(path.read_text(encoding="utf-8"))
        assert after["metadata"]["language_info"]["name"] == "python"
        for notebook in (before, after):
            notebook["metadata"].pop("language_info")
        if after != before:
            changed[name] = [key for key in ("metadata", "nbformat", "nbformat_minor") if after[key] != before[key]] + [
                index for index, (old, new) in enumerate(zip(before["cells"], after["cells"])) if old != new
            ]
        session["lab"].shut_down_kernel(f"handout/rotations-course/{name}")
    page.close()
    assert not dirty, f"marked modified as soon as they opened: {dirty}"
    assert not changed, f"changed by opening and saving (keys, cell numbers): {changed}"


@pytest.mark.parametrize("name", LESSONS)
def test_solved_lesson_reads_cleanly(session, name):
    """A reader's run of the solved lesson: math, figures, every check ✓, no stderr, no JS error."""
    page = _run(session, f"solutions/{name}")
    page.screenshot(path=str(ARTIFACTS / f"solutions_{name[:2]}.png"))
    PICTURES[name] = figure_pictures(page)
    problems = page_problems(page, LAB_SELECTORS, min_math=0 if name.startswith("00_") else 1)
    cells = page.evaluate("""() => [...document.querySelectorAll('.jp-Notebook .jp-CodeCell')].map(c => [
        (c.querySelector('.cm-content') || {}).textContent || '',
        [...c.querySelectorAll('.jp-OutputArea-output')].map(o => o.textContent).join('\\n')])""")
    # Start here shows on purpose what a failed check looks like, in a cell that catches CheckFailed.
    failed = [
        out[:120]
        for source, out in cells
        if "except CheckFailed" not in source and ("✗" in out or "NotWrittenYet" in out or "CheckFailed" in out)
    ]
    demonstrations = [out for source, out in cells if "except CheckFailed" in source]
    errors = page.locator(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.error']").count()
    nb = nbformat.read(SOLUTIONS / name, as_version=4)
    figure_cells = sum(
        1
        for c in nb.cells
        if c.cell_type == "code" and (re.search(r"plt\.show\(\)", c.source) or "explore_" in c.source)
    )
    figures = page.locator(".jp-OutputArea-output img").count() + page.locator(LAB_SELECTORS["canvases"]).count()
    names = live_figure_names(page)
    hand_in = _cell(page, "ready_to_hand_in(").locator(".jp-OutputArea").text_content() if nb_has_hand_in(name) else ""
    if name.startswith("03_"):  # Figure 3: two series apart without colour
        figure = page.locator(".jupyter-matplotlib-canvas-div[aria-label^='Figure 3.']").first
        figure.scroll_into_view_if_needed()
        figure.screenshot(path=str(ARTIFACTS / "solutions_03_figure_3.png"))
    page.close()
    assert not problems, problems
    assert len(names) >= (1 if figure_cells else 0), names
    unnamed = [
        (number, role, label)
        for number, (role, label) in enumerate(names, 1)
        if not re.match(r"Figure \d+[a-z]?\. \S", label)
    ]
    assert not unnamed, f"live figures (n-th on the page, role, name) without a caption: {unnamed}"
    assert all(role == "img" and not re.search(r"[$\\{}]", label) for role, label in names), names
    assert "[]" not in hand_in and "ready to hand in" in hand_in.lower() or not hand_in, hand_in
    assert not failed and not errors, (failed, errors)
    assert all("✗" in out for out in demonstrations), "the demonstration of a failed check shows no ✗"
    assert figures >= figure_cells, f"{figures} figures drawn for {figure_cells} figure cells"


@pytest.mark.parametrize("name", LESSONS)
def test_course_lesson_opens_and_runs(session, name):
    """A student's first Run All: math renders, no JS error, and (for a lesson with exercises) the
    first check cell stops the run with its one-line NotWrittenYet message."""
    page = _run(session, f"course/{name}")
    problems = page_problems(page, LAB_SELECTORS, min_math=0 if name.startswith("00_") else 1, check_stderr=False)
    nb = nbformat.read(COURSE / name, as_version=4)
    has_exercises = any("check(" in c.source for c in nb.cells if c.cell_type == "code")
    stopped = page.locator(".jp-OutputArea-output", has_text="NotWrittenYet").count()
    page.close()
    assert not problems, problems
    if has_exercises and not name.startswith("00_"):
        assert stopped >= 1, "the first check cell under a stub did not say NotWrittenYet"


def _cell(page, text):
    return page.locator(".jp-Notebook .jp-Cell", has=page.locator(".jp-InputArea", has_text=text)).first


def nb_has_hand_in(name):
    return any(c.get("id") == "ready-to-hand-in" for c in nbformat.read(SOLUTIONS / name, as_version=4).cells)


# Every live figure has its role and name, and the name is a caption ("Figure 2. ..."), not ipympl's
# default label ("Figure 2"): the kernel renames a figure when it draws it, a moment after its cell ran.
NAMED = r"""() => [...document.querySelectorAll('.jupyter-matplotlib-canvas-div')].every(c =>
  c.getAttribute('role') === 'img' && /^Figure \d+[a-z]?\. \S/.test(c.getAttribute('aria-label') || ''))"""


def live_figure_names(page, timeout_ms=20_000):
    """``[(role, accessible name)]`` of every live figure (ipympl canvas), as ``coursekit.plotting`` sets them.

    Waits (up to ``timeout_ms``) until every canvas is named by a caption, then reads the ``role`` and
    ``aria-label`` that Chromium's accessibility tree takes them from (``accessible_name`` reads the tree
    itself for one figure on screen); a canvas without them is ``(None, "")``.
    """
    try:
        page.wait_for_function(NAMED, timeout=timeout_ms, polling=250)
    except Exception:  # noqa: BLE001  (the names found are reported by the caller's assertion)
        pass
    return [
        (role, label or "")
        for role, label in page.evaluate(
            "() => [...document.querySelectorAll('.jupyter-matplotlib-canvas-div')]"
            ".map(c => [c.getAttribute('role'), c.getAttribute('aria-label')])"
        )
    ]


def accessible_name(locator):
    """``(role, name)`` of an element on screen as Chromium's accessibility tree holds it (Playwright's ARIA
    snapshot), e.g. ``("img", "Figure 2b. Gimbal at ...")``; ``(None, "")`` when it has none."""
    tree = locator.aria_snapshot().strip().splitlines()
    match = re.match(r'- (\w+)(?: "(.*)")?:?$', tree[0]) if tree else None
    return (match.group(1), json.loads(f'"{match.group(2) or ""}"')) if match else (None, "")


def test_a_worked_example_ahead_of_its_exercise_says_so_in_one_line(session):
    """Lesson 05 as handed out: Run All stops at the first check cell with one line (and says nothing of
    Run All); the student runs the next worked example anyway, which calls that unwritten exercise: one
    line naming it, no traceback."""
    name = next(n for n in LESSONS if n.startswith("05_"))
    page = _run(session, f"course/{name}")
    check = _cell(page, 'check("euler_zyx_to_matrix", euler_zyx_to_matrix)')
    stopped = check.locator(".jp-OutputArea").text_content()
    example = _cell(page, "R_wb = np.asarray(euler_zyx_to_matrix(")
    example.locator(".cm-content").click()
    page.keyboard.press("Shift+Enter")  # run just this cell
    page.wait_for_function(
        "(cell) => cell.querySelector('.jp-OutputArea-output')", arg=example.element_handle(), timeout=30_000
    )
    example.scroll_into_view_if_needed()
    said = example.locator(".jp-OutputArea").inner_text().strip()
    example.screenshot(path=str(ARTIFACTS / "course_05_worked_example_ahead.png"))
    check.locator(".cm-content").click()
    page.keyboard.press("Control+Enter")  # the check cell alone, not through Run All
    page.wait_for_timeout(1500)
    again = check.locator(".jp-OutputArea").inner_text()
    check.screenshot(path=str(ARTIFACTS / "course_05_check_cell_run_alone.png"))
    page.close()
    assert "euler_zyx_to_matrix is not written yet: write euler_zyx_to_matrix" in said, said
    assert len(said.splitlines()) == 1 and "Traceback" not in said and "File " not in said, said
    for text in (stopped, again):
        assert "not written yet" in text and "Traceback" not in text, text
        assert "Run All" not in text and "stopped here" not in text, text


def test_typed_answer_turns_a_check_green(session):
    """Type rot2d's answer into lesson 01's answer cell, run it and its check: ✗ becomes ✓."""
    name = next(n for n in LESSONS if n.startswith("01_"))
    page = _run(session, f"course/{name}")
    check = _cell(page, 'check("rot2d", rot2d)')
    check.scroll_into_view_if_needed()
    assert "NotWrittenYet" in check.locator(".jp-OutputArea").text_content()
    answer = _cell(page, "def rot2d(theta)")
    answer.locator(".cm-content").click()
    page.keyboard.press("Control+a")
    page.keyboard.insert_text(
        "import numpy as np\n\ndef rot2d(theta):\n"
        "    c, s = np.cos(theta), np.sin(theta)\n"
        "    return np.array([[c, -s], [s, c]])\n"
    )
    page.keyboard.press("Shift+Enter")  # run the answer, move to its check
    page.keyboard.press("Shift+Enter")  # run the check
    page.wait_for_function(
        "() => [...document.querySelectorAll('.jp-OutputArea-output')]"
        ".some(e => e.textContent.includes('rot2d: public checks') && e.textContent.includes('passed'))",
        timeout=30_000,
    )
    text = check.locator(".jp-OutputArea").text_content()
    page.screenshot(path=str(ARTIFACTS / "course_01_check_turned_green.png"))
    page.close()
    assert "✓" in text and "✗" not in text and "NotWrittenYet" not in text, text


def test_gimbal_slider_changes_the_figure(session):
    """Lesson 05's explorer: Tab reaches the pitch slider and End moves it, which redraws the gimbal."""
    name = next(n for n in LESSONS if n.startswith("05_"))
    page = _run(session, f"solutions/{name}")
    explorer = page.locator(".coursekit-explorer").first
    explorer.scroll_into_view_if_needed()
    canvas = explorer.locator(LAB_SELECTORS["canvases"]).first
    page.wait_for_timeout(500)
    before = canvas.evaluate("c => c.toDataURL()")
    handle = explorer.locator(".widget-slider", has_text="pitch").locator(".noUi-handle").first
    explorer.locator(".widget-slider", has_text="yaw").locator(".noUi-handle").first.focus()
    for _ in range(3):  # the keyboard alone reaches the next slider
        page.keyboard.press("Tab")  # (past the yaw slider's editable readout)
        if handle.evaluate("h => h === document.activeElement"):
            break
    assert handle.evaluate("h => h === document.activeElement"), "Tab from the yaw slider never reaches pitch"
    assert handle.get_attribute("role") == "slider"
    page.keyboard.press("End")  # pitch to +90°: the lock
    page.wait_for_function("([c, b]) => c.toDataURL() !== b", arg=[canvas.element_handle(), before], timeout=20_000)
    explorer.screenshot(path=str(ARTIFACTS / "solutions_05_gimbal_locked.png"))
    readout = explorer.locator(".widget-slider", has_text="pitch").locator(".widget-readout").text_content()
    locked = live_figure_names(page)
    for _ in range(3):  # off the lock by three steps: 88.5, not 88 or 89
        page.keyboard.press("ArrowLeft")
    page.wait_for_timeout(1500)
    near = explorer.locator(".widget-slider", has_text="pitch").locator(".widget-readout").text_content().strip()
    page.wait_for_function(
        "(text) => [...document.querySelectorAll('.coursekit-explorer "
        ".jupyter-matplotlib-canvas-div')].some(c => (c.getAttribute('aria-label') || '')"
        ".includes('pitch ' + text + '°'))",
        arg=near,
        timeout=20_000,
    )
    explorer.screenshot(path=str(ARTIFACTS / "solutions_05_gimbal_near_the_lock.png"))
    named = [label for _, label in live_figure_names(page) if "Gimbal at" in label]
    in_the_tree = accessible_name(canvas.locator("xpath=.."))  # the canvas's div, as a screen reader gets it
    page.close()
    assert readout.strip().startswith("90"), readout
    assert any("pitch 90°" in label for _, label in locked), locked
    assert near != "90" and "." in near, near  # a value between the steps, e.g. 88.5
    assert named and all(f"pitch {near}°" in label for label in named), (near, named)
    assert in_the_tree[0] == "img" and f"pitch {near}°" in in_the_tree[1], in_the_tree


def _broken_copy(root, name):
    """Lesson ``name`` broken five ways: two bad formulas, a warning on stderr, a missing image and a
    frame removed from Figure 1."""
    nb = nbformat.read(SOLUTIONS / name, as_version=4)
    figure = next(c for c in nb.cells if c.cell_type == "code" and "Figure 1." in c.source)
    frame = next(line for line in figure.source.splitlines() if line.startswith("draw_frame("))
    figure.source = figure.source.replace(frame + "\n", "", 1)
    nb.cells.insert(1, nbformat.v4.new_markdown_cell(r"A broken formula: $\frac{1}{2$ and $x^{1}^{2}$."))
    nb.cells.insert(
        2, nbformat.v4.new_code_cell("import warnings\nwarnings.warn('a RuntimeWarning on stderr', RuntimeWarning)")
    )
    nb.cells.insert(3, nbformat.v4.new_markdown_cell("![a figure that is not there](missing_figure.png)"))
    path = root / "solutions" / f"broken_{name}"
    nbformat.write(nb, path)
    return path.name


def test_the_browser_check_catches_each_breakage(session):
    """The check that passes the real lessons reports a bad formula, stderr output, a missing image and a
    figure drawn without one of its frames (against the figures of the real lesson, drawn in this session)."""
    name = next(n for n in LESSONS if n.startswith("01_"))
    if name not in PICTURES:  # the real lesson's figures, for reference
        page = _run(session, f"solutions/{name}")
        PICTURES[name] = figure_pictures(page)
        page.close()
    broken = _broken_copy(session["root"], name)
    page = _run(session, f"solutions/{broken}")
    page.screenshot(path=str(ARTIFACTS / "solutions_01_broken.png"))
    problems = page_problems(page, LAB_SELECTORS, min_math=1)
    problems += changed_figures(figure_pictures(page), PICTURES[name])
    page.close()
    joined = "\n".join(problems)
    assert "MathJax error" in joined or "raw TeX" in joined, problems
    assert "stderr output" in joined and "RuntimeWarning" in joined, problems
    assert "broken or empty image" in joined, problems
    assert "figure 1 differs from the lesson's" in joined, problems
    assert "figure 2 differs" not in joined, problems  # the other figures are drawn as in the lesson
