"""Plotting helpers shared by the lessons: frames as arrow triads, points, axes.

A frame is drawn as three arrows from its origin: x red, y green, z blue
(the usual "RGB = xyz" mnemonic), in shades that stay apart for colour-blind
readers (Okabe and Ito's palette), and with a line style each (x solid,
y dashed, z dotted) so that the triad reads even in black and white. The
arrows are the columns of the frame's rotation matrix, which is exactly what
a rotation matrix *is*.

In a live JupyterLab, ``interactive_figures()`` switches to ipympl's widget
backend, so that every 3D figure can be turned with the mouse; everywhere
else (grading, recording, the book) figures stay static pictures. A live
figure is a canvas, which a screen reader cannot read: ``name_live_figure``
gives it its caption as accessible name (in the book the caption is the
picture's alt text, see ``coursekit.edition``).
"""

import os

import matplotlib.pyplot as plt
import numpy as np
from matplotlib.ticker import MaxNLocator

from .captions import figure_caption

__all__ = [
    "AXIS_COLORS",
    "new_3d_axes",
    "draw_frame",
    "draw_point",
    "draw_frame_2d",
    "finish_3d_axes",
    "draw_slope",
    "draw_circle",
    "AXIS_STYLES",
    "interactive_figures",
    "live_front_end",
    "widgets_live",
    "hide_figure_header",
    "book_build",
    "keep_toolbar_off_axes",
    "name_live_figure",
    "name_live_figure_when_drawn",
]

# Okabe-Ito vermillion, bluish green and blue: red, green and blue that colour-blind readers tell apart.
AXIS_COLORS = ("#D55E00", "#009E73", "#0072B2")
# ... and a line style per axis, for readers (and printers) without colour.
AXIS_STYLES = ("solid", "dashed", "dotted")


def live_front_end():
    """True in a kernel that a running Jupyter server started for a notebook (JupyterLab, Notebook 7).

    Such kernels carry ``JPY_SESSION_NAME``; kernels started by nbclient (the
    grader's notebook stage, ``record``, ``preview``, the book) do not, and
    the grader's kernels also force matplotlib's ``agg`` backend.
    """
    if not os.environ.get("JPY_SESSION_NAME"):
        return False
    if os.environ.get("MPLBACKEND", "").lower() in ("agg", "pdf", "svg", "ps", "cairo", "template"):
        return False
    try:
        from IPython import get_ipython
    except ImportError:
        return False
    shell = get_ipython()
    return shell is not None and hasattr(shell, "kernel")


def book_build():
    """True in the kernels of ``python -m autograder book``, which set ``COURSEKIT_BOOK=1``.

    There the explorers embed precomputed frames under an offline slider, and
    ``interactive_figures()`` says that the other figures are still pictures.
    """
    return os.environ.get("COURSEKIT_BOOK") == "1"


def interactive_figures():
    """In a live JupyterLab, draw figures with ipympl's widget backend (``%matplotlib widget``).

    3D figures can then be turned by dragging them with the mouse, and the
    explorers of ``coursekit.explorers`` update their figure in place.
    Anywhere else (no front end, or ipympl not installed) this does nothing,
    so a notebook that calls it still runs under nbval, the grader and the
    book builder. It returns nothing, so the cell that calls it shows nothing, except
    in the book, where it says in one line that the figures there are pictures. In the
    lab it also names every live figure by its caption (``name_live_figure``), with a
    script in the page that no one sees.
    """
    if book_build():
        from IPython.display import Markdown, display

        display(Markdown("*In this book the figures are pictures and the explorers move through precomputed "
                         "frames; open the lesson in JupyterLab (see Start here) to turn the 3D figures with "
                         "the mouse.*"))
        return
    if not live_front_end():
        return
    try:
        import ipympl  # noqa: F401  (only: is it installed?)
        from IPython import get_ipython
    except ImportError:
        return
    shell = get_ipython()
    shell.run_line_magic("matplotlib", "widget")
    # The figure's own title says which figure it is: no "Figure 1" header above it. The header is a
    # trait of each canvas, so a pyplot hook (run on every new figure) turns it off figure by figure;
    # another names the figure by its caption each time it is drawn (its title is set after it is made).
    for name in ("hide_figure_header", "keep_toolbar_off_axes", "name_live_figure_when_drawn"):
        hook = f"{__name__}:{name}"
        if hook not in plt.rcParams["figure.hooks"]:
            plt.rcParams["figure.hooks"] = [*plt.rcParams["figure.hooks"], hook]
    if name_open_figures not in shell.events.callbacks["post_execute"]:
        shell.events.register("post_execute", name_open_figures)
    from IPython.display import Javascript, display

    display(Javascript(NAME_CANVASES_JS))


# In the page: every ipympl canvas is an image named by its figure label (set by name_live_figure to the
# figure's caption; ipympl shows it in the figure's header, which the course hides). Runs once per page,
# and again whenever the notebook's DOM changes (a new figure, a redrawn title).
NAME_CANVASES_JS = """
(() => {
  if (window.coursekitNamesFigures) return;
  window.coursekitNamesFigures = true;
  const name = () => document.querySelectorAll('.jupyter-matplotlib-figure').forEach(figure => {
    const header = figure.querySelector('.jupyter-matplotlib-header');
    const canvas = figure.querySelector('.jupyter-matplotlib-canvas-div');
    if (!header || !canvas) return;
    const label = header.textContent.trim();
    if (label && canvas.getAttribute('aria-label') !== label) {
      canvas.setAttribute('role', 'img');
      canvas.setAttribute('aria-label', label);
    }
  });
  let queued = false;
  new MutationObserver(() => {
    if (queued) return;
    queued = true;
    requestAnimationFrame(() => { queued = false; name(); });
  }).observe(document.body, {childList: true, subtree: true, characterData: true});
  name();
})();
"""


def name_live_figure(fig):
    """Give a live figure (an ipympl canvas) its caption as accessible name; a no-op for pictures.

    The caption is the figure's suptitle, else its first axes title, as
    readable text (``coursekit.captions``: "R_z(δ)", not TeX). ipympl keeps it
    as the figure's window title and label (its hidden header, and the name of
    a downloaded PNG); the page script ``NAME_CANVASES_JS`` makes the canvas an image named
    by it. ``interactive_figures`` makes every new figure call this when it is
    drawn (``name_live_figure_when_drawn``), so an explorer's figure, whose
    title changes with its sliders, is named anew at each redraw.

    Examples
    --------
    >>> fig = plt.figure()                                        # doctest: +SKIP
    >>> fig.suptitle("Figure 2. The gimbal at pitch $88.5°$")     # doctest: +SKIP
    >>> name_live_figure(fig).canvas._figure_label                # doctest: +SKIP
    'Figure 2. The gimbal at pitch 88.5°'
    """
    if hasattr(fig.canvas, "_figure_label"):
        caption = figure_caption(fig)
        manager = fig.canvas.manager
        if caption and manager is not None and manager.get_window_title() != caption:
            # The window title, not the label alone: the page asks for a refresh after every resize,
            # and a refresh re-sends the window title ("Figure 2" unless set), which would undo a
            # label set directly whenever no redraw followed it.
            manager.set_window_title(caption)
        elif caption and fig.canvas._figure_label != caption:
            fig.canvas._figure_label = caption
    return fig


def name_open_figures():
    """Name every open live figure by its caption (an IPython ``post_execute`` hook).

    When a cell ends its figures have their final titles, so they are named
    before the page first asks for them, whether or not a draw comes first
    (a busy kernel may answer the page's draw request late).
    """
    from matplotlib._pylab_helpers import Gcf

    for manager in Gcf.get_all_fig_managers():
        name_live_figure(manager.canvas.figure)


def name_live_figure_when_drawn(fig):
    """Call :func:`name_live_figure` each time ``fig`` is drawn (a pyplot figure hook; a no-op for pictures).

    A figure gets its title after it is made, and an explorer changes it with
    every redraw; a draw is when the title is final.
    """
    if hasattr(fig.canvas, "_figure_label"):
        fig.canvas.mpl_connect("draw_event", lambda _event: name_live_figure(fig))
    return fig


def hide_figure_header(fig):
    """Hide ipympl's "Figure N" header above ``fig`` (a no-op for figures that are pictures)."""
    if hasattr(fig.canvas, "header_visible"):
        fig.canvas.header_visible = False
    return fig


TOOLBAR_PX = 44  # ipympl's toolbar: one column of 32 px buttons, and a margin


def keep_toolbar_off_axes(fig):
    """Put ipympl's toolbar in a strip at the right of ``fig`` that no axes, label or legend uses.

    ipympl lays its toolbar over the canvas (absolutely positioned, by default
    at the left, over the y labels). Here it goes to the right, and the figure's
    layout (constrained, tight or none) leaves ``TOOLBAR_PX`` free there. A
    no-op for figures that are pictures.

    Examples
    --------
    >>> fig = keep_toolbar_off_axes(plt.figure(figsize=(6, 4), layout="constrained"))   # doctest: +SKIP
    """
    if not hasattr(fig.canvas, "toolbar_position"):
        return fig
    fig.canvas.toolbar_position = "right"
    free = 1.0 - TOOLBAR_PX / (fig.get_figwidth() * fig.dpi)
    engine = fig.get_layout_engine()
    if engine is not None and "rect" in engine.get():
        engine.set(rect=(0.0, 0.0, free, 1.0))
    elif engine is None:
        fig.subplots_adjust(right=min(fig.subplotpars.right, free - 0.02))
    return fig


def widgets_live():
    """True when figures are ipympl widgets (``interactive_figures()`` switched them on)."""
    return "ipympl" in plt.get_backend().lower() or plt.get_backend().lower() == "widget"


def new_3d_axes(title, limit=1.5, elev=22, azim=-58, ax=None, figsize=(5.2, 4.6), unit="m", zoom=1.0):
    """Make (or prepare) a 3D axes with labelled axes, equal scale and a title.

    Parameters
    ----------
    title : str
    limit : float
        Half-width of the cube shown, in ``unit``.
    elev, azim : float
        Viewing angles in degrees (matplotlib's convention).
    ax : mpl_toolkits.mplot3d.Axes3D, optional
        An existing 3D axes to prepare instead of a new figure.
    unit : str
        The length unit written on the axis labels.
    zoom : float
        Below 1 shrinks the box inside its panel, so that axis labels of
        several 3D panels side by side are not clipped (0.85 works well).

    Returns
    -------
    fig, ax

    Examples
    --------
    >>> fig, ax = new_3d_axes("The world frame")
    >>> draw_frame(ax, np.eye(3), name="w")
    """
    if ax is None:
        fig = plt.figure(figsize=figsize)
        ax = fig.add_subplot(projection="3d")
    else:
        fig = ax.figure
    lo, hi = (-limit, limit) if np.isscalar(limit) else limit
    ax.set_xlim(lo, hi)
    ax.set_ylim(lo, hi)
    ax.set_zlim(lo, hi)
    ax.set_box_aspect((1, 1, 1), zoom=zoom)
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.set_major_locator(MaxNLocator(nbins=4, steps=[1, 2, 2.5, 5, 10]))  # few ticks: no collisions
    ax.tick_params(pad=1)
    ax.set_xlabel(f"$x$ [{unit}]", labelpad=2)
    ax.set_ylabel(f"$y$ [{unit}]", labelpad=2)
    ax.set_zlabel(f"$z$ [{unit}]", labelpad=2)
    ax.view_init(elev=elev, azim=azim)
    ax.set_title(title)
    return fig, ax


def draw_frame(ax, R=None, origin=(0.0, 0.0, 0.0), name="", length=1.0, alpha=1.0, linewidth=2.0):
    """Draw a frame as three arrows: the columns of ``R`` placed at ``origin``.

    Parameters
    ----------
    ax : 3D axes
    R : array_like, shape (3, 3), optional
        Attitude of the frame in the plotted (world) frame; identity if omitted.
    origin : array_like, shape (3,)
        Where the frame's origin is, in the plotted frame.
    name : str
        Frame name used in the labels, e.g. ``"c"`` gives ``x_c``, ``y_c``, ``z_c``.
    length : float
        Arrow length.

    The x, y and z arrows differ in colour and in line style (solid, dashed,
    dotted), so that they can be told apart without colour.
    """
    R = np.eye(3) if R is None else np.asarray(R, dtype=float)
    o = np.asarray(origin, dtype=float)
    for k, (axis_name, color, style) in enumerate(zip("xyz", AXIS_COLORS, AXIS_STYLES)):
        direction = R[:, k] * length
        ax.quiver(*o, *direction, color=color, alpha=alpha, linewidth=linewidth,
                  arrow_length_ratio=0.15, linestyles=style)
        if name:
            tip = o + 1.12 * direction
            ax.text(*tip, f"${axis_name}_{{{name}}}$", color=color, alpha=alpha,
                    ha="center", va="center")


def draw_point(ax, p, label="", color="black", size=40):
    """Draw a point ``p`` (shape (3,)) with an optional label."""
    p = np.asarray(p, dtype=float)
    ax.scatter(*p, color=color, s=size, depthshade=False)
    if label:
        ax.text(*(p + 0.08), label, color=color)


def draw_frame_2d(ax, R=None, origin=(0.0, 0.0), name="", length=1.0, alpha=1.0):
    """Draw a 2D frame: the two columns of ``R`` (shape (2, 2)) at ``origin``."""
    R = np.eye(2) if R is None else np.asarray(R, dtype=float)
    o = np.asarray(origin, dtype=float)
    for k, (axis_name, color, style) in enumerate(zip("xy", AXIS_COLORS, AXIS_STYLES)):
        d = R[:, k] * length
        ax.annotate("", xy=o + d, xytext=o,
                    arrowprops=dict(arrowstyle="-|>", color=color, lw=2, alpha=alpha, linestyle=style))
        if name:
            ax.text(*(o + 1.15 * d), f"${axis_name}_{{{name}}}$", color=color, alpha=alpha,
                    ha="center", va="center")


def finish_3d_axes(ax, legend=None):
    """Tidy a 3D plot: light panes and an optional legend location."""
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.pane.set_alpha(0.08)
    if legend:
        ax.legend(loc=legend)


def draw_slope(ax, x, anchor, slope, label=None, color="0.45"):
    """On log-log axes, draw a dashed guide line y ∝ x**slope through ``anchor``.

    Parameters
    ----------
    ax : matplotlib axes (log-log)
    x : array_like
        The x values where the guide is drawn (its extent).
    anchor : (float, float)
        A point (x0, y0) the guide passes through.
    slope : float
        The power: 1 for first-order errors, 2 for second-order ones, -1 for rounding noise.
    label : str, optional
        Legend text; ``"slope 2"`` style labels read well.

    Examples
    --------
    >>> fig, ax = plt.subplots()
    >>> _ = ax.loglog([1e-4, 1e-1], [1e-8, 1e-2])
    >>> draw_slope(ax, [1e-4, 1e-1], (1e-4, 1e-8), 2, label="slope 2")
    """
    x = np.asarray(x, dtype=float)
    x0, y0 = anchor
    ax.loglog(x, y0 * (x / x0) ** slope, linestyle="--", linewidth=1.0, color=color, label=label)


def draw_circle(ax, u, v, radius=1.0, center=(0.0, 0.0, 0.0), **style):
    """Draw the circle ``center + radius (cos t u + sin t v)`` on a 3D axes.

    ``u`` and ``v`` are orthonormal vectors spanning the circle's plane (shape (3,)),
    for example two columns of a rotation matrix: a gimbal ring, or the path of an
    axis tip. ``style`` goes to ``ax.plot`` (color, linewidth, alpha, label, ...).

    Examples
    --------
    >>> fig, ax = new_3d_axes("A ring in the horizontal plane")
    >>> draw_circle(ax, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], radius=0.8, color="tab:blue")
    """
    t = np.linspace(0.0, 2.0 * np.pi, 121)
    u, v = np.asarray(u, dtype=float), np.asarray(v, dtype=float)
    points = np.asarray(center, dtype=float)[:, None] + radius * (np.outer(u, np.cos(t)) + np.outer(v, np.sin(t)))
    ax.plot(*points, **style)
