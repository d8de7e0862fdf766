"""The course as students and readers meet it: JupyterLab in a real browser.

Starts JupyterLab from this environment on loopback, opens notebooks in
headless Chromium (Debian's ``chromium`` driven by Playwright), runs all cells
from the Run menu, and checks what a person sees: rendered math, figures, and
the check cells' messages. Screenshots go to ``test-artifacts/browser/``.
"""

import json
import os
import secrets
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from autograder import cells
from autograder.notebook_files import read_master
from autograder.paths import COURSE, PROJECT_ROOT, SOLUTIONS

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
ARTIFACTS = PROJECT_ROOT / "test-artifacts" / "browser"
playwright = pytest.importorskip("playwright.sync_api")
pytestmark = pytest.mark.skipif(not Path(CHROMIUM).exists(), reason="Debian's chromium is not installed")

SETTINGS = {
    "@jupyterlab/notebook-extension/tracker.jupyterlab-settings": {"windowingMode": "none"},
    "@jupyterlab/apputils-extension/notification.jupyterlab-settings": {"fetchNews": "false",
                                                                        "checkForUpdates": False},
}


def _free_port():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


@pytest.fixture(scope="module")
def lab(tmp_path_factory):
    """A JupyterLab serving copies of course/ and solutions/, and a browser page factory."""
    root = tmp_path_factory.mktemp("lab")
    shutil.copytree(COURSE, root / "course", ignore=shutil.ignore_patterns("__pycache__"))
    shutil.copytree(SOLUTIONS, root / "solutions", ignore=shutil.ignore_patterns("__pycache__"))
    settings = root / ".settings"
    for name, values in SETTINGS.items():
        path = settings / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(json.dumps(values), encoding="utf-8")
    port, token = _free_port(), secrets.token_hex(16)
    env = dict(os.environ, JUPYTERLAB_SETTINGS_DIR=str(settings), JUPYTER_RUNTIME_DIR=str(root / ".runtime"),
               IPYTHONDIR=str(root / ".ipython"), MPLBACKEND="module://matplotlib_inline.backend_inline")
    env.pop("PYTEST_DISABLE_PLUGIN_AUTOLOAD", None)
    server = subprocess.Popen(
        [sys.executable, "-m", "jupyterlab", "--no-browser", "--allow-root", "--ip=127.0.0.1", f"--port={port}",
         f"--IdentityProvider.token={token}", f"--ServerApp.root_dir={root}"],
        env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL, start_new_session=True)
    base = f"http://127.0.0.1:{port}"
    deadline = time.monotonic() + 90
    while True:
        try:
            urllib.request.urlopen(f"{base}/api/status?token={token}", timeout=2)
            break
        except OSError:
            if time.monotonic() > deadline or server.poll() is not None:
                server.kill()
                raise RuntimeError("JupyterLab did not start")
            time.sleep(0.5)
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    with playwright.sync_playwright() as driver:
        browser = driver.chromium.launch(executable_path=CHROMIUM, args=[
            "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run", "--disable-background-networking",
            "--disable-component-update", "--disable-sync"])
        yield {"browser": browser, "base": base, "token": token}
        browser.close()
    server.terminate()
    try:
        server.wait(timeout=20)
    except subprocess.TimeoutExpired:
        server.kill()


def _run_all(lab, relative, shot_prefix):
    """Open a notebook, run all cells from the Run menu, wait until done; return the page."""
    page = lab["browser"].new_page(viewport={"width": 1400, "height": 1000})
    page.goto(f"{lab['base']}/lab/tree/{relative}?token={lab['token']}")
    page.wait_for_selector(".jp-NotebookPanel .jp-Cell", timeout=90_000)
    page.wait_for_function("() => document.querySelector('.jp-Notebook-ExecutionIndicator') !== null"
                           " && document.body.innerText.includes('Idle')", timeout=90_000)
    page.get_by_role("menuitem", name="Run", exact=True).click()
    page.get_by_role("menuitem", name="Run All Cells", exact=True).click()
    # Run All stops at the first error (a stub's check cell in course/): wait until nothing runs.
    settled = ("() => { const prompts = [...document.querySelectorAll('.jp-InputPrompt')].map(p => p.innerText);"
               " return prompts.some(t => /\\[\\d+\\]/.test(t)) && !prompts.some(t => t.includes('*')); }")
    page.wait_for_function(settled, timeout=240_000)
    page.wait_for_timeout(2000)
    page.wait_for_function(settled, timeout=240_000)  # still settled: the run is over
    page.wait_for_timeout(1500)  # let MathJax and images settle
    page.screenshot(path=str(ARTIFACTS / f"{shot_prefix}_top.png"))
    return page


def _outputs(page):
    return page.locator(".jp-OutputArea-output").all_inner_texts()


def test_course_notebook_as_a_student_sees_it(lab):
    name = sorted(p.name for p in COURSE.glob("01_*.ipynb"))[0]
    page = _run_all(lab, f"course/{name}", "course_01")
    assert page.locator(".jp-RenderedMarkdown mjx-container").count() > 5, "math is not rendered"
    figures = page.locator(".jp-OutputArea-output img")
    assert figures.count() >= 1, "no figure rendered"
    figures.first.scroll_into_view_if_needed()
    figures.first.screenshot(path=str(ARTIFACTS / "course_01_figure.png"))
    texts = _outputs(page)
    stub_message = [t for t in texts if "not written yet" in t and "raise NotImplementedError" in t]
    assert stub_message, "the check cell under an untouched stub did not say what to do"
    check_output = page.locator(".jp-OutputArea-output", has_text="not written yet").first
    check_output.scroll_into_view_if_needed()
    page.screenshot(path=str(ARTIFACTS / "course_01_check_cell.png"))
    page.close()


def test_solved_notebook_as_a_reader_sees_it(lab):
    path = sorted(SOLUTIONS.glob("01_*.ipynb"))[0]
    master = read_master(path)
    check_cells = sum(1 for c in master.cells if cells.is_check_cell(c))
    figure_cells = sum(1 for c in master.cells if c.cell_type == "code" and "plt.show()" in c.source)
    page = _run_all(lab, f"solutions/{path.name}", "solutions_01")
    assert page.locator(".jp-RenderedMarkdown mjx-container").count() > 5
    texts = _outputs(page)
    passed = [t for t in texts if "public check" in t and "passed" in t and "✗" not in t]
    assert len(passed) == check_cells, f"{len(passed)} of {check_cells} check cells passed"
    assert not any("✗" in t for t in texts)
    assert page.locator(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr']").count() == 0
    assert page.locator(".jp-OutputArea-output img").count() == figure_cells
    page.locator(".jp-OutputArea-output img").last.scroll_into_view_if_needed()
    page.screenshot(path=str(ARTIFACTS / "solutions_01_last_figure.png"))
    page.close()
