"""What a reader meets in the solved notebooks: quick, quiet, readable figures, and a way on.

Each master runs once, top to bottom, in a fresh kernel with the inline
backend (as in JupyterLab). A first injected cell records every figure at
``plt.show()``; a last one reports them. Then:

- the run takes under 60 s and raises nothing;
- nothing is written to stderr (no warnings);
- no output is a bare repr such as ``<Figure size ...>``;
- every figure has a title (its own or per panel) and every panel labelled
  axes with units;
- every lesson ends with a link to the next one.
"""

import json
import re
import time

import nbformat
import pytest

from autograder.authoring.execute import execute_notebook
from autograder.lessons import cells
from autograder.lessons.notebook_files import read_master
from autograder.lessons.paths import COURSE, SOLUTIONS

MASTERS = sorted(p.name for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb"))

RECORD_FIGURES = """
import json as _json
import matplotlib.pyplot as _plt
_FIGURES = []

def _describe(figure):
    panels = []
    for ax in figure.axes:
        if ax.get_label() == "<colorbar>":
            continue
        labels = {"x": ax.get_xlabel(), "y": ax.get_ylabel()}
        if hasattr(ax, "get_zlabel"):
            labels["z"] = ax.get_zlabel()
        has_data = bool(ax.lines or ax.collections or ax.patches or ax.images)
        panels.append({"title": ax.get_title(), "labels": labels, "has_data": has_data,
                       "visible": ax.axison})
    title = figure._suptitle.get_text() if figure._suptitle is not None else ""
    return {"suptitle": title, "panels": panels}

_original_show = _plt.show

def _recording_show(*args, **kwargs):
    for number in _plt.get_fignums():
        _FIGURES.append(_describe(_plt.figure(number)))
    return _original_show(*args, **kwargs)

_plt.show = _recording_show
"""
REPORT_FIGURES = "print('FIGURES:' + _json.dumps(_FIGURES))"
BARE_REPR = re.compile(r"^(<[\w.]+ (object )?at 0x[0-9a-f]+>|<Figure size|\[<matplotlib|Text\(|<matplotlib)")
UNIT = re.compile(r"\[[^\]]+\]|\([^)]+\)")


@pytest.fixture(scope="module")
def runs():
    return {}


def _run(runs, name):
    if name not in runs:
        nb = read_master(SOLUTIONS / name)
        nb.cells.insert(0, nbformat.v4.new_code_cell(RECORD_FIGURES))
        nb.cells.append(nbformat.v4.new_code_cell(REPORT_FIGURES))
        started = time.monotonic()
        execute_notebook(nb, cwd=SOLUTIONS, timeout=120, allow_errors=True)
        seconds = time.monotonic() - started
        report = "".join(o.get("text", "") for o in nb.cells[-1].get("outputs", []))
        figures = json.loads(report.split("FIGURES:", 1)[1]) if "FIGURES:" in report else None
        runs[name] = (nb, seconds, figures)
    return runs[name]


@pytest.mark.parametrize("name", MASTERS)
def test_runs_quickly_without_errors(runs, name):
    nb, seconds, figures = _run(runs, name)
    errors = [
        (i, o.get("ename"), o.get("evalue"))
        for i, c in enumerate(nb.cells)
        for o in c.get("outputs", [])
        if o.get("output_type") == "error"
    ]
    assert not errors, errors[:3]
    assert seconds < 60, f"{name} took {seconds:.0f} s"
    assert figures is not None


@pytest.mark.parametrize("name", MASTERS)
def test_prints_no_warnings(runs, name):
    nb, _, _ = _run(runs, name)
    stderr = [
        (i, o["text"][:300])
        for i, c in enumerate(nb.cells)
        for o in c.get("outputs", [])
        if o.get("output_type") == "stream" and o.get("name") == "stderr"
    ]
    assert not stderr, stderr[:3]


@pytest.mark.parametrize("name", MASTERS)
def test_no_bare_reprs(runs, name):
    nb, _, _ = _run(runs, name)
    bare = [
        (i, o["data"]["text/plain"][:80])
        for i, c in enumerate(nb.cells)
        for o in c.get("outputs", [])
        if o.get("output_type") == "execute_result" and BARE_REPR.match(o["data"].get("text/plain", ""))
    ]
    assert not bare, bare


@pytest.mark.parametrize("name", MASTERS)
def test_figures_have_titles_labels_and_units(runs, name):
    _, _, figures = _run(runs, name)
    problems = []
    for number, figure in enumerate(figures or [], start=1):
        panels = [p for p in figure["panels"] if p["has_data"] and p["visible"]]
        if not panels:
            continue
        if not figure["suptitle"] and not all(p["title"] for p in panels):
            problems.append(f"figure {number}: no title")
        for panel in panels:
            for axis, label in panel["labels"].items():
                if not label.strip():
                    problems.append(f"figure {number} ({panel['title'] or 'panel'}): no {axis} label")
                elif not UNIT.search(label):
                    problems.append(f"figure {number}: {axis} label {label!r} gives no unit, e.g. [rad] or (unitless)")
    assert not problems, problems


def test_figure_cells_end_with_show():
    """A figure cell ends with plt.show(), so no <Figure ...> repr is printed and the recorder sees it."""
    missing = []
    for name in MASTERS:
        for index, cell in enumerate(read_master(SOLUTIONS / name).cells):
            source = cells.source_text(cell)
            if (
                cell.cell_type == "code"
                and re.search(r"plt\.(figure|subplots)\(|new_3d_axes\(", source)
                and "plt.show()" not in source
            ):
                missing.append(f"{name} cell {index + 1}")
    assert not missing, missing


def test_every_lesson_links_to_the_next():
    names = sorted(p.name for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb"))
    for current, following in zip(names, names[1:] + [names[0]]):
        text = "\n".join(
            cells.source_text(c) for c in read_master(SOLUTIONS / current).cells[-3:] if c.cell_type == "markdown"
        )
        assert f"]({following})" in text, f"{current} does not end with a link to {following}"


def test_no_placeholder_text_anywhere_a_student_looks():
    pattern = re.compile(r"\b(TODO|FIXME|XXX|TBD)\b|lorem ipsum", re.IGNORECASE)
    found = []
    for folder in (COURSE, SOLUTIONS):
        for path in sorted(folder.rglob("*")):
            if path.suffix in (".ipynb", ".py", ".md") and "__pycache__" not in path.parts:
                for number, line in enumerate(path.read_text(encoding="utf-8").splitlines(), start=1):
                    if pattern.search(line):
                        found.append(f"{path.relative_to(folder.parent)}:{number}: {line.strip()[:80]}")
    assert not found, found[:10]


def test_start_page_lists_every_lesson_with_its_time():
    """00_start_here's table names each lesson, links to it, and quotes the time the lesson states."""
    start = "\n".join(
        cells.source_text(c) for c in read_master(SOLUTIONS / "00_start_here.ipynb").cells if c.cell_type == "markdown"
    )
    for name in MASTERS:
        if name.startswith("00_"):
            continue
        first = cells.source_text(read_master(SOLUTIONS / name).cells[0])
        title = first.splitlines()[0].split("—", 1)[1].strip()
        time_stated = re.search(r"\*\*Time:?\*\*:?\s*([^.\n]*)", first).group(1).strip()
        row = next((line for line in start.splitlines() if f"]({name})" in line), None)
        assert row is not None, f"00_start_here does not link to {name}"
        assert f"[{title}]" in row, f"00_start_here calls {name} something other than {title!r}"
        assert time_stated in row, f"00_start_here gives {name} a different time than its own {time_stated!r}"
