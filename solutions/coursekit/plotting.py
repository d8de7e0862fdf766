"""Plotting helpers shared by the lessons: frames as arrow triads, points, axes.

A frame is drawn as three arrows from its origin: x red, y green, z blue
(the usual "RGB = xyz" mnemonic). The arrows are the columns of the frame's
rotation matrix, which is exactly what a rotation matrix *is*.
"""

import matplotlib.pyplot as plt
import numpy as np

__all__ = [
    "AXIS_COLORS",
    "new_3d_axes",
    "draw_frame",
    "draw_point",
    "draw_frame_2d",
    "finish_3d_axes",
]

AXIS_COLORS = ("tab:red", "tab:green", "tab:blue")


def new_3d_axes(title, limit=1.5, elev=22, azim=-58, ax=None, figsize=(5.2, 4.6), unit="m"):
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
    ax.set_box_aspect((1, 1, 1))
    ax.set_xlabel(f"x [{unit}]")
    ax.set_ylabel(f"y [{unit}]")
    ax.set_zlabel(f"z [{unit}]")
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
    """
    R = np.eye(3) if R is None else np.asarray(R, dtype=float)
    o = np.asarray(origin, dtype=float)
    for k, (axis_name, color) in enumerate(zip("xyz", AXIS_COLORS)):
        direction = R[:, k] * length
        ax.quiver(*o, *direction, color=color, alpha=alpha, linewidth=linewidth,
                  arrow_length_ratio=0.15)
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
    for k, (axis_name, color) in enumerate(zip("xy", AXIS_COLORS)):
        d = R[:, k] * length
        ax.annotate("", xy=o + d, xytext=o,
                    arrowprops=dict(arrowstyle="-|>", color=color, lw=2, alpha=alpha))
        if name:
            ax.text(*(o + 1.15 * d), f"${axis_name}_{{{name}}}$", color=color, alpha=alpha,
                    ha="center", va="center")


def finish_3d_axes(ax, legend=None):
    """Tidy a 3D plot: light panes and an optional legend location."""
    for axis in (ax.xaxis, ax.yaxis, ax.zaxis):
        axis.pane.set_alpha(0.08)
    if legend:
        ax.legend(loc=legend)
