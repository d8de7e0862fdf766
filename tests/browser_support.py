"""Shared by the browser tests: Chromium through Playwright, a JupyterLab server, and what a page shows.

``page_problems(page)`` is the browser check itself: it lists what a person
would see go wrong on a page (raw TeX, a MathJax error, an empty or broken
image, a blank figure canvas, stderr output, a JavaScript error). The tests
assert it finds nothing on the real lessons and the real book, and that it
finds each kind of breakage on a copy broken on purpose.
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

CHROMIUM = shutil.which("chromium") or "/usr/bin/chromium"
CHROMIUM_ARGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--no-first-run",
    "--disable-quic",
]


def require_chromium():
    """Skip (with the reason) when Chromium or Playwright is missing; return playwright.sync_api."""
    if not Path(CHROMIUM).exists():
        pytest.skip("Debian's chromium is not installed (apt-get install -y chromium); the browser tests need it")
    return pytest.importorskip("playwright.sync_api", reason="the playwright package is not installed")


def free_port():
    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        return probe.getsockname()[1]


class Browser:
    """One headless Chromium; ``page()`` opens a page that records console errors and page errors."""

    def __init__(self, sync_api):
        self._driver = sync_api.sync_playwright().start()
        self.browser = self._driver.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)

    def page(self, width=1400, height=1000):
        page = self.browser.new_page(viewport={"width": width, "height": height})
        page.js_errors = []
        page.on(
            "console",
            lambda message: (
                page.js_errors.append(f"console.{message.type}: {message.text[:300]}")
                if message.type == "error"
                else None
            ),
        )
        page.on("pageerror", lambda error: page.js_errors.append(f"page error: {str(error)[:300]}"))
        return page

    def close(self):
        self.browser.close()
        self._driver.stop()


class JupyterLab:
    """A JupyterLab server from this environment on loopback, serving ``root``, with default settings."""

    def __init__(self, root):
        self.root = Path(root)
        settings = self.root / ".settings"
        news = settings / "@jupyterlab" / "apputils-extension" / "notification.jupyterlab-settings"
        news.parent.mkdir(parents=True, exist_ok=True)
        news.write_text('{"fetchNews": "false", "checkForUpdates": false}', encoding="utf-8")  # no pop-up
        self.port, self.token = free_port(), secrets.token_hex(16)
        env = dict(
            os.environ,
            JUPYTERLAB_SETTINGS_DIR=str(settings),
            JUPYTERLAB_WORKSPACES_DIR=str(self.root / ".workspaces"),
            JUPYTER_RUNTIME_DIR=str(self.root / ".runtime"),
            IPYTHONDIR=str(self.root / ".ipython"),
        )
        for name in ("MPLBACKEND", "PYTEST_DISABLE_PLUGIN_AUTOLOAD", "JPY_SESSION_NAME"):
            env.pop(name, None)
        self.server = subprocess.Popen(
            [
                sys.executable,
                "-m",
                "jupyterlab",
                "--no-browser",
                "--allow-root",
                "--ip=127.0.0.1",
                f"--port={self.port}",
                f"--IdentityProvider.token={self.token}",
                f"--ServerApp.root_dir={self.root}",
            ],
            env=env,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            start_new_session=True,
        )
        self.base = f"http://127.0.0.1:{self.port}"
        deadline = time.monotonic() + 90
        while True:
            try:
                urllib.request.urlopen(f"{self.base}/api/status?token={self.token}", timeout=2)
                break
            except OSError:
                if time.monotonic() > deadline or self.server.poll() is not None:
                    self.stop()
                    raise RuntimeError("JupyterLab did not start")
                time.sleep(0.5)

    def shut_down_kernel(self, relative):
        """End the kernel of ``relative`` if one runs, so the next page opens it with a fresh kernel.

        A page that is closed leaves its kernel running; a second page on the same notebook
        would join that kernel, whose widget models (ipympl canvases, sliders) the new page
        never created.
        """
        api = f"{self.base}/api/sessions"
        with urllib.request.urlopen(f"{api}?token={self.token}", timeout=10) as answer:
            sessions = json.load(answer)
        for found in sessions:
            if found.get("path") == relative or (found.get("notebook") or {}).get("path") == relative:
                request = urllib.request.Request(f"{api}/{found['id']}?token={self.token}", method="DELETE")
                urllib.request.urlopen(request, timeout=30).close()

    def url(self, relative):
        return f"{self.base}/lab/tree/{relative}?token={self.token}&reset"

    def stop(self):
        self.server.terminate()
        try:
            self.server.wait(timeout=20)
        except subprocess.TimeoutExpired:
            self.server.kill()


# Run All is over when the kernel is idle, no cell waits ([*]), some cell ran, and either the last code
# cell ran or the last cell that ran shows an error (Run All stops at the first error, such as a stub's
# check cell). JupyterLab renders an error as an application/vnd.jupyter.stderr output, like a warning.
# The notebook's outputs and prompts are cleared first, so a stored execution count cannot pass for a run.
SETTLED = r"""() => {
  if (!document.body.innerText.includes('Idle')) return false;
  const cells = [...document.querySelectorAll('.jp-Notebook .jp-CodeCell')];
  const prompts = cells.map(c => (c.querySelector('.jp-InputPrompt') || {}).textContent || '');
  if (!prompts.length || prompts.some(t => t.includes('*'))) return false;
  const counts = prompts.map(t => { const m = t.match(/\[(\d+)\]/); return m ? +m[1] : 0; });
  const latest = Math.max(...counts);
  if (!latest) return false;
  if (counts[counts.length - 1]) return true;
  const last = cells[counts.indexOf(latest)];
  return !!last.querySelector(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr']");
}"""


def open_and_run_all(lab, page, relative, timeout_ms=180_000):
    """Open a notebook in JupyterLab (with a fresh kernel), run all cells from the Run menu and wait
    until nothing runs, figures are drawn and math is typeset."""
    lab.shut_down_kernel(relative)
    page.goto(lab.url(relative))
    page.wait_for_selector(".jp-NotebookPanel .jp-Cell", timeout=90_000)
    page.wait_for_function("() => document.body.innerText.includes('Idle')", timeout=90_000)
    page.get_by_role("menuitem", name="Edit", exact=True).click()
    page.get_by_role("menuitem", name="Clear Outputs of All Cells", exact=True).click()
    page.get_by_role("menuitem", name="Run", exact=True).click()
    page.get_by_role("menuitem", name="Run All Cells", exact=True).click()
    page.wait_for_function(SETTLED, timeout=timeout_ms)
    page.wait_for_timeout(800)
    page.wait_for_function(SETTLED, timeout=timeout_ms)  # still settled: the run is over
    settle_figures(page)
    settle_math(page)


# An ipympl canvas is drawn when the kernel's first image arrives, a moment after its cell ran.
FIGURES_DRAWN = """(selector) => [...document.querySelectorAll(selector)].every(c => {
  if (!c.width || !c.height) return false;
  const data = c.getContext('2d').getImageData(0, 0, c.width, c.height).data;
  let ink = 0;
  for (let i = 0; i < data.length; i += 4 * 97) if (data[i + 3] > 0 && (data[i] < 200 || data[i + 1] < 200 || data[i + 2] < 200)) ink++;
  return ink >= 20;
})"""


def settle_figures(page, timeout_ms=15_000):
    """Wait until every figure canvas shows its picture (one still blank after that is reported)."""
    try:
        page.wait_for_function(FIGURES_DRAWN, arg=LAB_SELECTORS["canvases"], timeout=timeout_ms, polling=250)
    except Exception:  # noqa: BLE001  (a canvas that stays blank is reported by page_problems)
        pass


def settle_math(page, timeout_ms=8_000):
    """Wait until MathJax has typeset the rendered markdown (no formula left in raw form)."""
    page.wait_for_timeout(1000)
    try:
        page.wait_for_function(
            "() => ![...document.querySelectorAll('.jp-RenderedMarkdown')].some(e => /\\$[^$]+\\$/.test(e.innerText))",
            timeout=timeout_ms,
        )
    except Exception:  # noqa: BLE001  (a page with raw TeX is reported by page_problems)
        pass


# A page of the book typesets its math when MathJax's startup promise resolves; a page without math
# (the start page) may not load MathJax at all.
BOOK_MATH_DONE = """async () => {
  if (!document.querySelector('.math')) return 0;
  for (let i = 0; i < 600 && !(window.MathJax && MathJax.startup && MathJax.startup.promise); i++)
    await new Promise(r => setTimeout(r, 50));
  if (!(window.MathJax && MathJax.startup && MathJax.startup.promise)) return -1;
  await MathJax.startup.promise;
  return document.querySelectorAll('.math').length;
}"""


def open_book_page(page, path):
    """Open a page of the book from disk and wait until it is loaded and its math typeset.

    Returns the number of formulas the page holds (-1 when MathJax never started on a page with math).
    """
    page.goto(path.as_uri())
    page.wait_for_load_state("load")
    return page.evaluate(BOOK_MATH_DONE)


# What a reader should never see. Runs in the page; returns a list of problems (strings).
PAGE_PROBLEMS_JS = r"""
(opts) => {
  const problems = [];
  const visible = el => !!(el.offsetWidth || el.offsetHeight || el.getClientRects().length);
  // 1. raw TeX: math delimiters or TeX commands left in rendered prose (code excluded)
  const prose = [...document.querySelectorAll(opts.prose)];
  for (const el of prose) {
    const copy = el.cloneNode(true);
    // (a .math span of the book stays: once typeset it holds an mjx-container, and raw text left in
    // it is a formula MathJax did not find, such as one with an unclosed brace)
    copy.querySelectorAll('code, pre, mjx-container, .MathJax, script, style').forEach(n => n.remove());
    const text = copy.textContent;
    const m = text.match(/\$\$?[^$\n]{1,80}\$|\\\(|\\\[|\\(frac|mathbf|mathrm|operatorname|alpha|theta|sum|begin)\b/);
    if (m) problems.push('raw TeX: ' + JSON.stringify(m[0].slice(0, 60)));
  }
  // 2. MathJax errors
  // (CommonHTML output, as in JupyterLab, has mjx-merror elements; SVG output, as in the book, marks the
  // error's group with data-mjx-error; an undefined macro is drawn as red text by the noundefined extension)
  for (const el of document.querySelectorAll('mjx-merror, .MathJax_Error, [data-mjx-error], .mjx-merror')) {
    problems.push('MathJax error: ' + (el.getAttribute('data-mjx-error') || el.textContent).slice(0, 80));
  }
  for (const el of document.querySelectorAll(
      'mjx-container [data-mml-node="mtext"][fill="red"], mjx-container mjx-mtext[style*="color: red"]')) {
    problems.push('MathJax error: undefined macro ' + (el.closest('mjx-container').textContent || '').slice(0, 60));
  }
  if (opts.minMath && document.querySelectorAll('mjx-container').length < opts.minMath)
    problems.push('math not rendered: ' + document.querySelectorAll('mjx-container').length + ' formulas');
  // 3. images: loaded and not empty
  for (const img of document.querySelectorAll(opts.images)) {
    if (!img.complete || img.naturalWidth === 0 || img.naturalHeight === 0)
      problems.push('broken or empty image: ' + (img.getAttribute('src') || '').slice(0, 60));
  }
  // 4. figure canvases (ipympl): drawn, not blank
  for (const canvas of document.querySelectorAll(opts.canvases)) {
    if (!canvas.width || !canvas.height) { problems.push('empty figure canvas'); continue; }
    const data = canvas.getContext('2d').getImageData(0, 0, canvas.width, canvas.height).data;
    let ink = 0;
    for (let i = 0; i < data.length; i += 4 * 97) if (data[i + 3] > 0 && (data[i] < 200 || data[i + 1] < 200 || data[i + 2] < 200)) ink++;
    if (ink < 20) problems.push('blank figure canvas');
  }
  // 5. stderr
  for (const el of document.querySelectorAll(opts.stderr)) {
    problems.push('stderr output: ' + el.textContent.trim().slice(0, 120));
  }
  return problems;
}
"""

LAB_SELECTORS = {
    "prose": ".jp-MarkdownCell .jp-RenderedMarkdown",
    "images": ".jp-OutputArea-output img, .jp-RenderedMarkdown img",
    "canvases": ".jupyter-matplotlib-canvas-div canvas:first-child",
    "stderr": ".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr']",
}
BOOK_SELECTORS = {
    "prose": "article.bd-article p, article.bd-article li, article.bd-article td, article.bd-article h1,"
    " article.bd-article h2, article.bd-article h3",
    "images": "img",
    "canvases": "canvas",
    "stderr": ".output.stderr, .cell_output .stderr",
}


PICTURES_JS = """() => [...document.querySelectorAll(
    '.jp-OutputArea-output img, .jupyter-matplotlib-canvas-div canvas:first-child')]
    .map(e => e.tagName === 'CANVAS' ? e.toDataURL() : e.getAttribute('src'))"""


def figure_pictures(page, timeout_s=10):
    """Every figure the notebook shows, in order, as a data URL of its pixels (ipympl canvas or PNG).

    Read until two reads a second apart agree: an ipympl canvas may still receive a redraw.
    """
    pictures = page.evaluate(PICTURES_JS)
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        page.wait_for_timeout(1000)
        again = page.evaluate(PICTURES_JS)
        if again == pictures:
            break
        pictures = again
    return pictures


def changed_figures(pictures, reference):
    """Problems for figures that are missing or drawn differently from ``reference`` (the real lesson's)."""
    problems = [
        f"figure {k + 1} differs from the lesson's"
        for k, (got, want) in enumerate(zip(pictures, reference))
        if got != want
    ]
    if len(pictures) != len(reference):
        problems.append(f"{len(pictures)} figures drawn, the lesson draws {len(reference)}")
    return problems


def page_problems(page, selectors, min_math=1, check_stderr=True):
    """Everything wrong that ``page`` shows, as short strings (an empty list for a good page)."""
    opts = dict(selectors, minMath=min_math)
    if not check_stderr:
        opts["stderr"] = ".no-such-element"
    problems = page.evaluate(PAGE_PROBLEMS_JS, opts)
    problems += page.js_errors
    return problems
