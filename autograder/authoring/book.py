"""The book: a static website of the solved lessons, for readers without Python.

``python -m autograder book --out _build/book`` copies the masters of
``solutions/`` (the reference answers, without nbgrader's solution markers)
and the ``coursekit`` package they import into a staging folder, executes
every notebook with Sphinx, myst-nb and sphinx-book-theme, and writes the
HTML to ``--out``. The front page is ``00_start_here``; open
``OUT/index.html`` in any browser: math is typeset by a copy of MathJax inside
the book, so it reads offline, from disk, with no server and no Python.

It is the reader's edition: cells a master tags ``student-only`` (check cells,
hand-in, grading) are left out, the lab's "your ``boxminus``" reads "the reference
``boxminus``" (``book_phrases``), its kernels run with ``COURSEKIT_EDITION=reader``
(legends say "the reference log_so3", not "your log_so3"), and every figure's
alt text is its caption.

What the book never holds: the course's stubs (``course/``), the hidden
tests and the grader (``autograder/``), the public checks' source or the
notebooks' sources (only the executed pages).

Examples
--------
>>> out, pages, warnings = build_book("_build/book")          # doctest: +SKIP
"""

from __future__ import annotations

import json
import os
import re
import shutil
import subprocess
import sys
import tempfile
from html import escape as html_escape
from pathlib import Path

import nbformat

from autograder.authoring.book_phrases import reader_phrasing
from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master

FRONT_PAGE = "00_start_here"
SUPPORT_PACKAGE = "coursekit"
SOLUTION_MARKERS = ("### BEGIN SOLUTION", "### END SOLUTION")
READER_EDITION_VARIABLE = "COURSEKIT_EDITION"  # read by solutions/coursekit/edition.py

CONF_PY = """\
project = {title}
author = "the course authors"
copyright = "the course authors"
extensions = ["myst_nb"]
root_doc = "index"
exclude_patterns = ["_build", "coursekit", "**.ipynb_checkpoints", "jupyter_execute"]
myst_enable_extensions = ["dollarmath", "amsmath"]
myst_heading_anchors = 3
# "$$ ... $$" inside a paragraph or a list item (as the lessons write it), display math as in JupyterLab
myst_dmath_double_inline = True
nb_execution_mode = "force"
nb_execution_timeout = {timeout}
nb_execution_raise_on_error = True
nb_execution_show_tb = True
nb_merge_streams = True
html_theme = "sphinx_book_theme"
html_title = {title}
html_copy_source = False
html_show_sourcelink = False
html_static_path = ["_static"]
html_theme_options = {{"show_toc_level": 2, "use_download_button": False, "use_fullscreen_button": False,
                      "use_repository_button": False, "home_page_in_toc": True}}
# The theme reads its colour mode from localStorage or else from default_mode; without one it logs
# "Got invalid theme mode" as a console error on every page of a book opened from disk. Light mode also
# suits the figures, which are drawn on white.
html_context = {{"default_mode": "light"}}
html_last_updated_fmt = None
mathjax_path = "mathjax/tex-svg-full.js"
mathjax3_config = {{"tex": {{"inlineMath": [["\\\\(", "\\\\)"]], "displayMath": [["\\\\[", "\\\\]"]]}}}}
suppress_warnings = ["mystnb.unknown_mime_type", "myst.header"]
"""


class BookFailed(RuntimeError):
    """Sphinx could not build the book (a lesson raised, or a page could not be written)."""


def _mathjax_file():
    """MathJax 3's self-contained SVG build, shipped by the ``django-static-mathjax`` wheel (no Django needed)."""
    import mathjax

    path = Path(mathjax.__file__).parent / "static" / "mathjax" / "es5" / "tex-svg-full.js"
    if not path.is_file():
        raise BookFailed(f"MathJax is missing ({path}): pip install -r environment.txt")
    return path


_POINTS_IN_HEADING = re.compile(r"^(#+ Exercise \d+: .*?) \(\d+(?:\.\d+)? points?\)[ \t]*$", re.MULTILINE)


def _reader_copy(nb):
    """The master as a reader sees it: answers in place, without nbgrader's solution markers, and
    without the cells tagged student-only (check cells, hand-in, how grading works), without the points
    in exercise headings, and in the reader's wording ("the reference `boxminus`", not "your `boxminus`":
    ``book_phrases``)."""
    nb.cells = [cell for cell in nb.cells if not cells.is_student_only(cell)]
    for cell in nb.cells:
        if cell.cell_type in ("markdown", "code"):
            cell.source = reader_phrasing(cell.source)
        if cell.cell_type == "markdown":
            cell.source = _POINTS_IN_HEADING.sub(r"\1", cell.source)  # points are the grader's business
        if cell.cell_type == "code":
            lines = cell.source.splitlines()
            kept = [line for line in lines if line.strip() not in SOLUTION_MARKERS]
            if len(kept) != len(lines):
                cell.source = "\n".join(kept)
            cell.outputs, cell.execution_count = [], None
    return nb


_PATH_AS_ALT = re.compile(r'<img alt="(_images/[^"]+\.png)" src="\1"')


def _alt_text_from_captions(page, root):
    """Give every figure of ``page`` its caption as alt text (docutils' default is the file path).

    The book's kernels write each figure's caption into its PNG's ``Title``
    text chunk (``coursekit.edition``); a figure without a caption gets
    "Figure without a caption" rather than a file name.
    """
    from PIL import Image

    def alt(match):
        with Image.open(root / match.group(1)) as image:
            caption = image.text.get("Title", "") if hasattr(image, "text") else ""
        return f'<img alt="{html_escape(caption or "Figure without a caption")}" src="{match.group(1)}"'

    text = page.read_text(encoding="utf-8")
    changed = _PATH_AS_ALT.sub(alt, text)
    if changed != text:
        page.write_text(changed, encoding="utf-8")


def _front_page(title):
    """A start page for a course without ``00_start_here.ipynb``: its title, then the lessons."""
    return nbformat.v4.new_notebook(
        cells=[
            nbformat.v4.new_markdown_cell(
                f"# {title}\n\nThe solved lessons, to read and run. Each one opens with what it teaches."
            )
        ]
    )


def stage(solutions_dir: str | Path, staging: str | Path, title: str = "") -> list[str]:
    """Write the book's sources into ``staging``: the solved lessons, coursekit, conf.py and MathJax.

    The start page is the course's ``00_start_here.ipynb``; a course without one gets a page with
    ``title`` and the list of lessons.
    """
    solutions_dir, staging = Path(solutions_dir), Path(staging)
    masters = sorted(solutions_dir.glob("[0-9][0-9]_*.ipynb"))
    if not masters:
        raise BookFailed(f"{solutions_dir} has no lessons (NN_*.ipynb)")
    if FRONT_PAGE not in (path.stem for path in masters):
        made = staging / f"{FRONT_PAGE}.ipynb"
        nbformat.write(_front_page(title or solutions_dir.parent.name), made)
        masters.insert(0, made)
    names = [path.stem for path in masters]
    for path in masters:
        nb = _reader_copy(read_master(path))
        target = staging / path.name
        if path.stem == FRONT_PAGE:
            lessons = "\n".join(name for name in names if name != FRONT_PAGE)
            nb.cells.append(
                nbformat.v4.new_markdown_cell(
                    f"```{{toctree}}\n:hidden:\n:maxdepth: 1\n:caption: Lessons\n\n{lessons}\n```"
                )
            )
        nbformat.write(nb, target)
    # index.html is what a reader opens: it is the start page itself.
    shutil.copyfile(staging / f"{FRONT_PAGE}.ipynb", staging / "index.ipynb")
    (staging / f"{FRONT_PAGE}.ipynb").unlink()
    shutil.copytree(
        solutions_dir / SUPPORT_PACKAGE,
        staging / SUPPORT_PACKAGE,
        ignore=shutil.ignore_patterns("__pycache__", "*.pyc"),
    )
    (staging / "_static" / "mathjax").mkdir(parents=True)
    shutil.copyfile(_mathjax_file(), staging / "_static" / "mathjax" / "tex-svg-full.js")
    return names


def build_book(
    out: str | Path,
    solutions_dir: str | Path,
    title: str,
    timeout: float = 180,
    jobs: int = 2,
    keep_staging: str | Path | None = None,
) -> tuple[Path, list[str], str]:
    """Build the book of the course whose masters are in ``solutions_dir`` into ``out`` (replaced); return
    (out, the lesson names, Sphinx's warnings as text). ``title``: the course's, on every page.

    Raises BookFailed with Sphinx's own report when a lesson raises or the
    build fails. Warnings are also written to ``OUT/../book-warnings.txt`` when there are any.
    """
    out = Path(out).resolve()
    with tempfile.TemporaryDirectory(prefix="book-") as tmp:
        staging = Path(keep_staging) if keep_staging else Path(tmp) / "src"
        if staging.exists():
            shutil.rmtree(staging)
        staging.mkdir(parents=True)
        names = stage(solutions_dir, staging, title)
        (staging / "conf.py").write_text(CONF_PY.format(timeout=timeout, title=json.dumps(title)), encoding="utf-8")
        # Links between lessons point at NN_topic.ipynb; the start page is index now.
        for path in staging.glob("*.ipynb"):
            text = path.read_text(encoding="utf-8")
            if f"({FRONT_PAGE}.ipynb" in text:
                path.write_text(text.replace(f"({FRONT_PAGE}.ipynb", "(index.ipynb"), encoding="utf-8")
        html = Path(tmp) / "html"
        env = {
            key: value
            for key, value in os.environ.items()
            if key not in ("JPY_SESSION_NAME", "MPLBACKEND", "PYDEVD_DISABLE_FILE_VALIDATION")
        }
        env["PYTHONHASHSEED"] = "0"
        env[READER_EDITION_VARIABLE] = "reader"  # coursekit.edition: "the reference log_so3", not "your"
        env["PYDEVD_DISABLE_FILE_VALIDATION"] = "1"
        env["COURSEKIT_BOOK"] = "1"  # explorers embed precomputed frames under an offline slider (coursekit)
        warnings = Path(tmp) / "warnings.txt"
        run = subprocess.run(
            [
                sys.executable,
                "-m",
                "sphinx",
                "-b",
                "html",
                "-q",
                "-j",
                str(jobs),
                "-d",
                str(Path(tmp) / "doctrees"),
                "-w",
                str(warnings),
                str(staging),
                str(html),
            ],
            env=env,
            cwd=staging,
            capture_output=True,
            text=True,
        )
        if run.returncode != 0 or not (html / "index.html").is_file():
            raise BookFailed(f"sphinx-build failed (exit {run.returncode}):\n{run.stderr[-4000:]}")
        for leftover in (".buildinfo", ".doctrees", "_sources", "jupyter_execute", ".jupyter_cache", "objects.inv"):
            target = html / leftover
            if target.is_dir():
                shutil.rmtree(target)
            elif target.exists():
                target.unlink()
        for page in html.glob("*.html"):
            _alt_text_from_captions(page, html)
        if out.exists():
            shutil.rmtree(out)
        out.parent.mkdir(parents=True, exist_ok=True)
        shutil.copytree(html, out)
        report = out.parent / "book-warnings.txt"
        text = warnings.read_text(encoding="utf-8") if warnings.exists() else ""
        if text.strip():
            report.write_text(text, encoding="utf-8")
        elif report.exists():
            report.unlink()
    return out, names, text
