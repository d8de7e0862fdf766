"""Every figure of every lesson fits the column it is shown in, and its text reads at that size.

One subprocess runs the code cells of every solved lesson once (Agg backend,
as the book's and the grader's kernels run them; about 40 s on the course
machine) and measures each figure when it is shown (``plt.show``) or closed
(an explorer's frames in the book, see ``coursekit.explorers``):

- **JupyterLab**: the output column is about 1,000 px wide with the file
  browser open; figures are drawn at ``figure.dpi`` = 100, one image pixel
  per CSS pixel, so a figure (its canvas, or its tight bounding box as the
  inline backend saves it) is at most ``LAB_COLUMN_PX`` wide.
- **The book**: sphinx-book-theme's article column is 783 px wide at a
  1400 px window (790 px at 1920; measured in Chromium); a wider picture is
  scaled down to the column, and every text of the figure scaled with it
  must stay at least ``MIN_FONT_PT`` (9 pt) tall.

The PNGs, at the size a reader sees them, go to ``test-artifacts/figures/``.
Run ``python tests/test_figure_sizes.py OUT_JSON [PNG_DIR]`` to survey by hand.
"""

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent
SOLUTIONS = ROOT / "solutions"
ARTIFACTS = ROOT / "test-artifacts" / "figures"
LAB_COLUMN_PX = 1000
BOOK_COLUMN_PX = 783
MIN_FONT_PT = 9.0
DPI = 100  # matplotlib's figure.dpi, used by the inline backend, ipympl and the book alike


def _measure(fig, where):
    """Width of ``fig`` in the lab and in the book, and its smallest text as the book shows it."""
    from matplotlib.text import Text

    fig.set_dpi(DPI)
    renderer = fig.canvas.get_renderer()
    fig.draw(renderer)  # runs the layout engine, as saving does
    tight = fig.get_tightbbox(renderer).width * DPI  # the inline PNG (bbox_inches="tight")
    canvas = fig.get_figwidth() * DPI  # the ipympl canvas, and an explorer's frame
    shown = max(tight, canvas) if where == "frame" else tight
    scale = min(1.0, BOOK_COLUMN_PX / shown)
    texts = [
        t
        for t in fig.findobj(Text)
        if t.get_visible() and t.get_text().strip() and t.figure is fig and _on_figure(t, renderer, fig)
    ]
    smallest = min(texts, key=lambda t: t.get_fontsize(), default=None)
    return {
        "where": where,
        "title": _title(fig),
        "lab_px": round(max(tight, canvas)),
        "book_px": round(shown),
        "scale": round(scale, 3),
        "min_font_pt": None if smallest is None else round(smallest.get_fontsize() * scale, 2),
        "min_font_text": None if smallest is None else smallest.get_text()[:60],
    }


def _on_figure(text, renderer, fig):
    """Tick labels outside the axes' view limits exist but are never drawn: skip them."""
    try:
        box = text.get_window_extent(renderer)
    except Exception:  # noqa: BLE001 - a text that cannot be placed is not drawn either
        return False
    return box.width > 0 and box.height > 0 and box.x1 > 0 and box.x0 < fig.bbox.width


def _title(fig):
    titles = [fig._suptitle.get_text()] if getattr(fig, "_suptitle", None) else []
    titles += [ax.get_title() for ax in fig.axes if ax.get_title()]
    return (titles or ["(untitled)"])[0][:80]


def survey(out_json, png_dir=None):
    """Run every solved lesson's code cells; write one record per figure to ``out_json``."""
    import matplotlib

    matplotlib.use("agg")
    import matplotlib.pyplot as plt
    import nbformat
    from IPython.core.interactiveshell import InteractiveShell

    from matplotlib.animation import Animation

    def last_frame_only(animation, *args, **kwargs):
        # The survey measures the frames' figure, not the film: draw the last frame (pitch 90° for the
        # gimbal) and skip encoding the rest, which the book build and test_book.py do for real.
        animation._fig.canvas.mpl_disconnect(animation._first_draw_id)  # no restart at frame 0 on the next draw
        animation._draw_frame(list(animation.new_frame_seq())[-1])
        return ""

    Animation.to_jshtml = last_frame_only
    sys.path.insert(0, str(SOLUTIONS))
    os.chdir(SOLUTIONS)
    records, seen = [], {}  # id -> the figure itself: kept alive, so that a new figure never reuses a measured one's id
    shell = InteractiveShell.instance()
    real_close = plt.close
    lesson = {"name": ""}

    def record(fig, where):
        if seen.get(id(fig)) is fig:
            return
        seen[id(fig)] = fig
        entry = dict(_measure(fig, where), lesson=lesson["name"])
        if png_dir:
            path = Path(png_dir) / f"{lesson['name'][:2]}_{len(records):02d}.png"
            fig.savefig(path, dpi=DPI * entry["scale"], bbox_inches=None if where == "frame" else "tight")
            entry["png"] = str(path)
        records.append(entry)

    def show(*args, **kwargs):
        for number in plt.get_fignums():
            record(plt.figure(number), "picture")
        real_close("all")

    def close(fig=None):
        figures = (
            [plt.figure(n) for n in plt.get_fignums()]
            if fig in (None, "all")
            else ([fig] if hasattr(fig, "canvas") else [])
        )
        for figure in figures:
            record(figure, "frame")
        real_close(fig)

    plt.show, plt.close = show, close
    for path in sorted(SOLUTIONS.glob("[0-9][0-9]_*.ipynb")):
        lesson["name"] = path.stem
        shell.reset(new_session=False)
        nb = nbformat.read(path, as_version=4)
        for cell in nb.cells:
            if cell.cell_type == "code":
                result = shell.run_cell(cell.source.replace("%matplotlib", "# %matplotlib"), silent=True)
                if not result.success:  # a syntax error, or an exception while running
                    raise RuntimeError(f"{path.name}: {result.error_before_exec or result.error_in_exec!r}")
        show()
    Path(out_json).write_text(json.dumps(records, indent=1), encoding="utf-8")


@pytest.fixture(scope="module")
def figures(tmp_path_factory):
    out = tmp_path_factory.mktemp("figures") / "figures.json"
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    for old in ARTIFACTS.glob("*.png"):
        old.unlink()
    env = dict(os.environ, MPLBACKEND="Agg", PYTHONHASHSEED="0", COURSEKIT_BOOK="1")
    env.pop("JPY_SESSION_NAME", None)
    run = subprocess.run(
        [sys.executable, __file__, str(out), str(ARTIFACTS)],
        cwd=ROOT,
        env=env,
        capture_output=True,
        text=True,
        timeout=600,
    )
    assert run.returncode == 0, run.stderr[-3000:]
    print(f"figures: PNGs at the size shown in the book in {ARTIFACTS}")
    return json.loads(out.read_text(encoding="utf-8"))


def _describe(entry):
    return f"{entry['lesson']} {entry['title']!r}"


def test_every_lesson_draws_figures_and_every_explorer_has_frames(figures):
    lessons = {entry["lesson"] for entry in figures}
    masters = {p.stem for p in SOLUTIONS.glob("[0-9][0-9]_*.ipynb") if not p.stem.startswith("00_")}
    assert masters <= lessons, f"no figure measured in {sorted(masters - lessons)}"
    explorers = sum(
        source.read_text(encoding="utf-8").count("explore_") for source in SOLUTIONS.glob("[0-9][0-9]_*.ipynb")
    )
    assert explorers and sum(entry["where"] == "frame" for entry in figures) >= 5


def test_every_figure_fits_the_jupyterlab_column(figures):
    wide = [f"{_describe(e)}: {e['lab_px']} px" for e in figures if e["lab_px"] > LAB_COLUMN_PX]
    assert not wide, f"wider than the {LAB_COLUMN_PX} px output column of JupyterLab:\n" + "\n".join(wide)


def test_every_text_reads_at_9_pt_as_the_book_shows_it(figures):
    small = [
        f"{_describe(e)}: {e['min_font_text']!r} at {e['min_font_pt']} pt ({e['book_px']} px wide, shown at "
        f"{e['scale']:.2f})"
        for e in figures
        if e["min_font_pt"] is not None and e["min_font_pt"] < MIN_FONT_PT
    ]
    assert not small, f"text under {MIN_FONT_PT} pt at the size the book shows:\n" + "\n".join(small)


def test_the_measure_sees_a_wide_figure_and_small_text():
    """The oracle itself: a 12 in figure is too wide for the lab, and its 10 pt ticks shrink under 9 pt in the book."""
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(figsize=(12, 4), layout="constrained")
    ax.set_title("wide")
    entry = _measure(fig, "picture")
    plt.close(fig)
    assert entry["lab_px"] > LAB_COLUMN_PX and entry["min_font_pt"] < MIN_FONT_PT
    fig, ax = plt.subplots(figsize=(6, 4), layout="constrained")
    ax.set_title("fits")
    entry = _measure(fig, "picture")
    plt.close(fig)
    assert entry["lab_px"] <= BOOK_COLUMN_PX and entry["min_font_pt"] == 10.0


if __name__ == "__main__":
    survey(*sys.argv[1:])
