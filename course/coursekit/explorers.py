"""Explorers: figures with sliders, for turning a rotation and watching what follows.

Each explorer draws one figure from a few numbers (angles, a step size, an
iteration count) and shows sliders for them:

- in a live JupyterLab with ipympl (``coursekit.plotting.interactive_figures()``)
  the sliders redraw the figure in place, and 3D panels still turn with the mouse;
- in a live front end without ipympl, the sliders redraw an ordinary picture;
- in the book (``python -m autograder book``), the explorer's main control is
  swept through a few dozen precomputed frames under an offline JavaScript
  slider (matplotlib's ``Animation.to_jshtml``), with a line saying so;
- anywhere else (the grader's notebook stage, ``record``) the explorer draws
  one static figure that makes the same point, and no widget.

Explorers use ``coursekit.lie`` (built on scipy), never the functions you
write in the exercises, so an unfinished answer cannot break them. Nothing
here is graded.

Examples
--------
>>> explore_gimbal(figure="2b")          # doctest: +SKIP
"""

import re
from html import escape as html_escape

import matplotlib.pyplot as plt
import numpy as np
from scipy.spatial.transform import Rotation, Slerp

from .lie import Exp, Log, skew
from .captions import figure_caption
from .plotting import (AXIS_COLORS, book_build, draw_circle, draw_frame, draw_point, finish_3d_axes, hide_figure_header,
                       keep_toolbar_off_axes, live_front_end, new_3d_axes, widgets_live)

__all__ = ["explore_exp", "explore_slerp", "explore_gimbal", "explore_step_size", "explore_gauss_newton", "draw_gimbal"]

BOOK_FRAME_DPI = 100  # as figure.dpi in the lessons: a frame is as big as the live figure
RING_COLORS = ("#0072B2", "#009E73", "#E69F00")  # yaw (outer), pitch (middle), roll (inner, orange: not the x axis's vermilion) rings


# ---------------------------------------------------------------------------------------------------------
# The machinery shared by every explorer
# ---------------------------------------------------------------------------------------------------------

# How a slider prints its value; a title that repeats the value uses the same format, so both say 88.5.
READOUT_FORMAT = ".3g"


def _slider(spec):
    import ipywidgets as widgets

    label, low, high, step, value = spec
    return widgets.FloatSlider(value=value, min=low, max=high, step=step, description=label,
                               continuous_update=True, readout_format=READOUT_FORMAT,
                               style={"description_width": "initial"},
                               layout=widgets.Layout(width="340px"))


def _views(fig):
    return [(ax.elev, ax.azim) if hasattr(ax, "elev") else None for ax in fig.axes]


def _restore(fig, views):
    for ax, view in zip(fig.axes, views):
        if view is not None and hasattr(ax, "view_init"):
            ax.view_init(elev=view[0], azim=view[1])


def _explore(draw, controls, figsize, static, static_figsize=None, sweep=None):
    """Show ``draw(fig, **values)`` with a slider per control, or ``draw(fig, **static)`` as a picture.

    ``controls`` maps a keyword of ``draw`` to ``(label, min, max, step, start)``.
    ``sweep`` = ``(name, first, last, count)``: in the book (``book_build()``) the
    explorer is ``count`` frames of that one control, under a slider that needs no kernel.
    Returns None: the explorer is displayed here, and a returned widget would be
    displayed a second time as the cell's value (two views of one ipympl canvas).
    """
    if widgets_live():
        import ipywidgets as widgets
        from IPython.display import display

        sliders = {name: _slider(spec) for name, spec in controls.items()}
        with plt.ioff():
            fig = plt.figure(figsize=figsize, layout="constrained")
        hide_figure_header(fig)
        keep_toolbar_off_axes(fig)

        def update(_change=None):
            views = _views(fig)
            fig.clear()
            draw(fig, **{name: s.value for name, s in sliders.items()})
            if len(views) == len(fig.axes):
                _restore(fig, views)
            fig.canvas.draw_idle()

        for s in sliders.values():
            s.observe(update, names="value")
        update()
        box = widgets.VBox([widgets.HBox(list(sliders.values()), layout=widgets.Layout(flex_flow="row wrap")),
                            fig.canvas])
        box.add_class("coursekit-explorer")
        display(box)
        return None
    if live_front_end():
        try:
            import ipywidgets as widgets
            from IPython.display import display
        except ImportError:
            widgets = None
        if widgets is not None:
            sliders = {name: _slider(spec) for name, spec in controls.items()}

            def redraw(**values):
                fig = plt.figure(figsize=figsize, layout="constrained")
                draw(fig, **values)
                plt.show()

            out = widgets.interactive_output(redraw, sliders)
            box = widgets.VBox([widgets.HBox(list(sliders.values()),
                                             layout=widgets.Layout(flex_flow="row wrap")), out])
            box.add_class("coursekit-explorer")
            display(box)
            return None
    if sweep is not None and book_build():
        _show_frames(draw, controls, figsize, sweep)
        return None
    fig = plt.figure(figsize=static_figsize or figsize, layout="constrained")
    draw(fig, static=True, **static)
    plt.show()
    return None


def _show_frames(draw, controls, figsize, sweep):
    """The book's explorer: ``draw`` at every value of one control, as a slider of frames that needs no kernel.

    ``sweep`` is ``(name, first, last, count)``; the other controls stay at their
    start values. matplotlib's ``Animation.to_jshtml`` embeds the frames (
    JPEG at the lessons' 100 dpi) and a JavaScript slider in the page.
    """
    from IPython.display import HTML, display
    from matplotlib.animation import FuncAnimation

    name, first, last, count = sweep
    values = np.linspace(first, last, count)
    fixed = {key: spec[4] for key, spec in controls.items() if key != name}
    with plt.ioff():
        fig = plt.figure(figsize=figsize, layout="constrained", dpi=BOOK_FRAME_DPI)

    def frame(k):
        fig.clear()
        draw(fig, **fixed, **{name: values[k]})

    animation = FuncAnimation(fig, frame, frames=count, init_func=lambda: frame(0), repeat=False)
    with plt.rc_context({"animation.frame_format": "jpeg"}):   # half the size of PNG frames (1.4 MB for 31)
        html = animation.to_jshtml(fps=6, default_mode="once")
    frame(0)
    caption = _caption_of(fig)
    plt.close(fig)
    label = controls[name][0]
    # matplotlib links Font Awesome from a CDN for its buttons' icons: a book read offline loads nothing remote
    html = re.sub(r'<link[^>]*font-awesome[^>]*>', "", html)
    html = html.replace('name="points"', f'name="points" aria-label="{label}: frame"')
    alt = html_escape(f"{caption} (precomputed frames: {label} from {first:g} to {last:g})", quote=True)
    html = re.sub(r'<img id="(_anim_img\w+)"', lambda m: f'<img id="{m.group(1)}" alt="{alt}"', html)
    kept = ", ".join(f"{controls[key][0]} = {value:g}" for key, value in fixed.items())
    note = (f"In this book the explorer is {count} precomputed frames: drag the slider below (or focus it and "
            f"press the arrow keys, Home, End) to move <b>{label}</b> from {first:g} to {last:g}"
            + (f", with {kept}" if kept else "") + ". Open the lesson in JupyterLab to move every slider and "
            "turn the 3D view.")
    display(HTML(f'<div class="coursekit-explorer-frames"><p>{note}</p>{html}</div>'))


def _caption_of(fig):
    """The figure's title as one line of readable text (its suptitle, else its first axes' title): the frames'
    alt text and the live figure's accessible name."""
    return figure_caption(fig) or "An explorer's frames"


def _title(figure, text):
    return f"Figure {figure}. {text}" if figure is not None else text


# ---------------------------------------------------------------------------------------------------------
# Lesson 03: axis and angle drive Exp
# ---------------------------------------------------------------------------------------------------------

def _unit_axis(azimuth_deg, elevation_deg):
    a, e = np.deg2rad(azimuth_deg), np.deg2rad(elevation_deg)
    return np.array([np.cos(e) * np.cos(a), np.cos(e) * np.sin(a), np.sin(e)])


def explore_exp(figure=None):
    """Axis and angle sliders drive R = Exp(θ u): the frame turns about u, its axis tips trace circles.

    The static picture shows the frame at θ = 0 (faint) and at θ = 2 rad, with
    the circle each axis tip travels on as θ runs from 0 to 2π.
    """
    def draw(fig, azimuth, elevation, theta, static=False):
        u = _unit_axis(azimuth, elevation)
        R = Exp(theta * u)
        ax = fig.add_subplot(projection="3d")
        new_3d_axes(_title(figure, "Exp turns the frame about its axis u by the angle θ"), ax=ax,
                    limit=1.3, zoom=0.9)
        ax.plot(*np.column_stack([-1.3 * u, 1.3 * u]), color="black", linewidth=1.4, linestyle="dashdot",
                label=r"axis $\mathbf{u}$")
        draw_frame(ax, np.eye(3), alpha=0.25)
        for k, color in enumerate(AXIS_COLORS):
            e = np.eye(3)[:, k]
            center = (e @ u) * u                     # a tip circles about the axis, in the plane ⟂ u
            radial = e - center
            r = np.linalg.norm(radial)
            if r > 1e-9:
                draw_circle(ax, radial / r, np.cross(u, radial / r), radius=r, center=center,
                            color=color, linewidth=0.8, alpha=0.45)
                arc = np.array([Exp(t * u) @ e for t in np.linspace(0.0, theta, 40)]).T
                ax.plot(*arc, color=color, linewidth=2.0, alpha=0.9)
        draw_frame(ax, R, name="b", linewidth=2.5)
        w = theta * u
        ax.text2D(0.02, 0.02, rf"$\theta$ = {theta:.2f} rad,  $\mathbf{{w}} = \theta\mathbf{{u}}$ = "
                  f"({w[0]:.2f}, {w[1]:.2f}, {w[2]:.2f}) rad", transform=ax.transAxes, fontsize=9)
        ax.legend(loc="upper left", fontsize=9)
        finish_3d_axes(ax)

    controls = {"azimuth": ("axis azimuth [°]", -180.0, 180.0, 1.0, 30.0),
                "elevation": ("axis elevation [°]", -90.0, 90.0, 1.0, 40.0),
                "theta": ("angle θ [rad]", 0.0, 2 * np.pi, 0.01, 2.0)}
    return _explore(draw, controls, (6.4, 5.6), {"azimuth": 30.0, "elevation": 40.0, "theta": 2.0},
                    sweep=("theta", 0.0, 2 * np.pi, 33))


# ---------------------------------------------------------------------------------------------------------
# Lesson 04: slerp against lerp
# ---------------------------------------------------------------------------------------------------------

def _quat_matrix(q):
    return Rotation.from_quat(np.asarray(q, dtype=float), scalar_first=True).as_matrix()


def explore_slerp(figure=None, q0=None, q1=None):
    """Slide t from 0 to 1: slerp and normalised lerp (nlerp) between two attitudes, side by side.

    Left: the path of the body's x axis on the unit sphere, with a dot at every
    tenth of t for each method (slerp's dots are evenly spaced; nlerp's crowd
    together near the ends and spread out in the middle, where it turns fastest).
    Right: the angle turned so far against t (a straight line for slerp, an S
    for nlerp).
    """
    q0 = np.array([1.0, 0.0, 0.0, 0.0]) if q0 is None else np.asarray(q0, dtype=float)
    q1 = Rotation.from_rotvec([0.4, 1.4, 2.6]).as_quat(scalar_first=True) if q1 is None else np.asarray(q1, float)
    q0, q1 = q0 / np.linalg.norm(q0), q1 / np.linalg.norm(q1)
    if q0 @ q1 < 0:
        q1 = -q1                                         # the shorter arc
    keys = Rotation.from_quat(np.array([q0, q1]), scalar_first=True)
    slerp = Slerp([0.0, 1.0], keys)

    def lerp(t):
        return (1.0 - t) * q0 + t * q1

    def draw(fig, t, static=False):
        ax = fig.add_subplot(2, 1, 1, projection="3d")     # stacked: the lesson column is narrow
        ax2 = fig.add_subplot(2, 1, 2)
        new_3d_axes("the body's x axis on the unit sphere", ax=ax, limit=1.15, zoom=0.85, unit="unitless")
        ax.set_xlabel("$x$ (unitless)")
        ax.set_ylabel("$y$ (unitless)")
        ax.set_zlabel("$z$ (unitless)")
        s = np.linspace(0, 2 * np.pi, 25)
        for lat in np.linspace(-60, 60, 5):
            c = np.cos(np.deg2rad(lat))
            ax.plot(c * np.cos(s), c * np.sin(s), np.full_like(s, np.sin(np.deg2rad(lat))), color="0.85",
                    linewidth=0.6)
        ts = np.linspace(0.0, 1.0, 101)
        tenths = np.linspace(0.0, 1.0, 11)
        path_s = slerp(ts).as_matrix()[:, :, 0]
        path_n = np.array([_quat_matrix(lerp(x) / np.linalg.norm(lerp(x)))[:, 0] for x in ts])
        ax.plot(*path_s.T, color="#0072B2", linewidth=2.0, label="slerp")
        ax.plot(*path_n.T, color="#E69F00", linewidth=2.0, linestyle="--", label="nlerp")
        dots_s = slerp(tenths).as_matrix()[:, :, 0]
        dots_n = np.array([_quat_matrix(lerp(x) / np.linalg.norm(lerp(x)))[:, 0] for x in tenths])
        ax.scatter(*dots_s.T, color="#0072B2", s=14, marker="o", depthshade=False)
        ax.scatter(*dots_n.T, color="#E69F00", s=22, marker="x", depthshade=False)
        R_s = slerp([t]).as_matrix()[0]
        draw_frame(ax, R_s, name="s", length=0.8, linewidth=2.2)
        ax.legend(loc="upper left", fontsize=9)
        finish_3d_axes(ax)

        angle_s = [np.linalg.norm(Log(_quat_matrix(q0).T @ m)) for m in slerp(ts).as_matrix()]
        angle_n = [np.linalg.norm(Log(_quat_matrix(q0).T @ _quat_matrix(lerp(x) / np.linalg.norm(lerp(x)))))
                   for x in ts]
        ax2.plot(ts, angle_s, color="#0072B2", linewidth=2.0, label="slerp: angle turned")
        ax2.plot(ts, angle_n, color="#E69F00", linewidth=2.0, linestyle="--", label="nlerp: angle turned")
        ax2.axvline(t, color="black", linewidth=0.9)
        ax2.plot([t], [np.interp(t, ts, angle_s)], "o", color="#0072B2")
        ax2.plot([t], [np.interp(t, ts, angle_n)], "X", color="#E69F00")
        ax2.set_xlabel("interpolation parameter $t$ (unitless)")
        ax2.set_ylabel("angle from $q_0$ [rad]")
        ax2.set_title(f"at t = {t:.2f}: slerp {np.interp(t, ts, angle_s):.3f} rad, "
                      f"nlerp {np.interp(t, ts, angle_n):.3f} rad", fontsize=10)
        ax2.grid(True, alpha=0.3)
        ax2.legend(loc="upper left", fontsize=9)
        fig.suptitle(_title(figure, "Slerp turns at constant speed; normalised lerp hurries through the middle"))

    return _explore(draw, {"t": ("t (unitless)", 0.0, 1.0, 0.01, 0.3)}, (7.0, 9.4), {"t": 0.3},
                    sweep=("t", 0.0, 1.0, 21))


# ---------------------------------------------------------------------------------------------------------
# Lesson 05: the gimbal
# ---------------------------------------------------------------------------------------------------------

def _Rx(a):
    return Exp([a, 0.0, 0.0])


def _Ry(a):
    return Exp([0.0, a, 0.0])


def _Rz(a):
    return Exp([0.0, 0.0, a])


def draw_gimbal(ax, yaw, pitch, roll, title, legend=True):
    """Draw three nested gimbal rings turned by z-y-x Euler angles [rad], and the body they carry.

    The outer ring turns about the world z axis (yaw), the middle one about the
    outer ring's y axis (pitch), the inner one and the body about the middle
    ring's x axis (roll); each ring holds its own pivot axis and the next one's.
    The caption gives the angle between the roll and yaw axes, 0 at gimbal lock.

    Examples
    --------
    >>> ax = plt.figure().add_subplot(projection="3d")                     # doctest: +SKIP
    >>> draw_gimbal(ax, 0.4, np.deg2rad(88.0), 0.3, "near the lock")       # doctest: +SKIP
    """
    R1 = _Rz(yaw)
    R2 = R1 @ _Ry(pitch)
    R3 = R2 @ _Rx(roll)
    new_3d_axes(title, ax=ax, limit=1.25, elev=18, azim=-50, zoom=0.85)
    styles = ("solid", "dashed", "dotted")
    draw_circle(ax, R1[:, 1], R1[:, 2], radius=1.05, color=RING_COLORS[0], linewidth=2.2, alpha=0.8)
    draw_circle(ax, R2[:, 0], R2[:, 1], radius=0.88, color=RING_COLORS[1], linewidth=2.2, alpha=0.8)
    draw_circle(ax, R3[:, 0], R3[:, 1], radius=0.72, color=RING_COLORS[2], linewidth=2.2, alpha=0.8)
    for axis, color, style, label in [(np.array([0.0, 0.0, 1.0]), RING_COLORS[0], styles[0], "yaw axis"),
                                      (R1[:, 1], RING_COLORS[1], styles[1], "pitch axis"),
                                      (R2[:, 0], RING_COLORS[2], styles[2], "roll axis")]:
        ax.plot(*np.column_stack([-1.25 * axis, 1.25 * axis]), linestyle=style, color=color, linewidth=1.6,
                label=label)
    draw_frame(ax, R3, name="b", length=0.55, linewidth=2.5)
    gap = np.degrees(np.arccos(np.clip(abs(R2[:, 0] @ np.array([0.0, 0.0, 1.0])), 0.0, 1.0)))
    locked = abs(np.cos(pitch)) < 0.05
    ax.text2D(0.02, 0.02, f"angle between roll and yaw axes: {gap:.1f}°" + ("  ← gimbal lock" if locked else ""),
              transform=ax.transAxes, fontsize=9, color="#D55E00" if locked else "black")
    if legend:
        ax.legend(loc="upper left", fontsize=9)
    finish_3d_axes(ax)


def explore_gimbal(figure=None):
    """Yaw, pitch and roll sliders turn three nested rings and the body they carry.

    Watch the angle between the roll axis and the yaw axis as pitch nears ±90°:
    at the lock the two axes coincide, yaw and roll do the same thing, and one
    direction of turning is lost. The static picture shows pitch 30° beside 88°.
    """
    def draw(fig, yaw, pitch, roll, static=False):
        if static:
            for k, p in enumerate((30.0, 88.0)):
                ax = fig.add_subplot(2, 1, k + 1, projection="3d")
                draw_gimbal(ax, np.deg2rad(yaw), np.deg2rad(p), np.deg2rad(roll),
                             f"yaw {yaw:.0f}°, pitch {p:.0f}°, roll {roll:.0f}°", legend=k == 0)
            fig.suptitle(_title(figure, "Turn the gimbal: near pitch 90° the roll axis meets the yaw axis"))
            return
        ax = fig.add_subplot(projection="3d")
        draw_gimbal(ax, np.deg2rad(yaw), np.deg2rad(pitch), np.deg2rad(roll),
                     _title(figure, f"Gimbal at yaw {yaw:{READOUT_FORMAT}}°, pitch {pitch:{READOUT_FORMAT}}°, "
                                    f"roll {roll:{READOUT_FORMAT}}° "
                                    f"(cos pitch = {np.cos(np.deg2rad(pitch)):.2f})"))

    controls = {"yaw": ("yaw ψ [°]", -180.0, 180.0, 1.0, 25.0),
                "pitch": ("pitch θ [°]", -90.0, 90.0, 0.5, 30.0),
                "roll": ("roll φ [°]", -180.0, 180.0, 1.0, 20.0)}
    return _explore(draw, controls, (6.4, 5.8), {"yaw": 25.0, "pitch": 30.0, "roll": 20.0},
                    static_figsize=(6.4, 10.6), sweep=("pitch", 0.0, 90.0, 31))


# ---------------------------------------------------------------------------------------------------------
# Lesson 06: the step-size V-curve
# ---------------------------------------------------------------------------------------------------------

def explore_step_size(figure=None, R=None, p=None):
    """Move the step h along the V-curve of a numerical Jacobian of Exp(δ) R p, forward and central.

    Left of the V's bottom, rounding noise grows like 1/h; right of it, the
    truncation error grows like h (forward) or h² (central).
    """
    R = Exp([0.3, -0.5, 0.8]) if R is None else np.asarray(R, dtype=float)
    p = np.array([1.0, 2.0, -0.5]) if p is None else np.asarray(p, dtype=float)
    J_exact = -skew(R @ p)          # the left perturbation's Jacobian (lesson 06, section 6)

    def jacobian(h, central):
        columns = []
        for axis in np.eye(3):
            ahead = Exp(h * axis) @ R @ p
            behind = Exp(-h * axis) @ R @ p if central else R @ p
            columns.append((ahead - behind) / (2 * h if central else h))
        return np.column_stack(columns)

    steps = np.logspace(-15, -1, 57)
    forward = np.array([np.max(np.abs(jacobian(h, False) - J_exact)) for h in steps])
    central = np.array([np.max(np.abs(jacobian(h, True) - J_exact)) for h in steps])
    floor = 1e-17

    def draw(fig, log10_h, static=False):
        h = 10.0 ** log10_h
        ax = fig.add_subplot()
        ax.loglog(steps, np.maximum(forward, floor), "o-", markersize=3, color="#D55E00",
                  label="forward difference")
        ax.loglog(steps, np.maximum(central, floor), "s--", markersize=3, color="#0072B2",
                  label="central difference")
        e_f = max(np.max(np.abs(jacobian(h, False) - J_exact)), floor)
        e_c = max(np.max(np.abs(jacobian(h, True) - J_exact)), floor)
        ax.axvline(h, color="black", linewidth=1.0)
        ax.plot([h], [e_f], "o", markersize=9, color="#D55E00", markeredgecolor="black")
        ax.plot([h], [e_c], "s", markersize=9, color="#0072B2", markeredgecolor="black")
        if static:
            best = steps[int(np.argmin(central))]
            ax.axvline(best, color="#0072B2", linewidth=1.0, linestyle=":")
        ax.set_xlabel("step $h$ [rad]")
        ax.set_ylabel(r"max $|J_{\mathrm{numerical}} - J_{\mathrm{exact}}|$ [m/rad]")
        ax.set_title(_title(figure, f"A movable step: at h = {h:.1e} rad the forward error is {e_f:.1e}, "
                                    f"the central {e_c:.1e}"), fontsize=10.5)
        ax.set_ylim(1e-14, 1e2)
        ax.grid(True, which="major", alpha=0.3)
        ax.legend(loc="upper center", fontsize=9)

    return _explore(draw, {"log10_h": ("log₁₀ of the step h [rad]", -15.0, -1.0, 0.1, -6.0)}, (7.6, 4.8),
                    {"log10_h": -6.0}, sweep=("log10_h", -15.0, -1.0, 29))


# ---------------------------------------------------------------------------------------------------------
# Lesson 08: Gauss-Newton, one iteration at a time
# ---------------------------------------------------------------------------------------------------------

def _gauss_newton_path(align_gauss_newton, P, Q, R0, iters):
    """``([R0, R1, ..., R_iters], problem)``: your ``align_gauss_newton`` run for 1, 2, ... iterations.

    Stops at the first iteration count that raises or returns no 3×3 matrix;
    ``problem`` then says why (else it is None).
    """
    path = [np.asarray(R0, dtype=float)]
    for k in range(1, iters + 1):
        try:
            R = np.asarray(align_gauss_newton(P, Q, np.array(R0, dtype=float), iters=k), dtype=float)
        except NotImplementedError:
            return path, "write align_gauss_newton (the exercise above) to step through its iterations here"
        except Exception as error:  # noqa: BLE001 - a student's function may fail in any way
            return path, f"align_gauss_newton(..., iters={k}) raised {type(error).__name__}: {error}"
        if R.shape != (3, 3) or not np.all(np.isfinite(R)):
            return path, f"align_gauss_newton(..., iters={k}) returned no finite 3×3 matrix"
        path.append(R)
    return path, None


def explore_gauss_newton(align_gauss_newton, figure=None, P=None, Q=None):
    """Step through your Gauss-Newton iterations: where R_k sends the body directions, and the cost per step.

    Parameters
    ----------
    align_gauss_newton : callable
        Your ``align_gauss_newton(P, Q, R0, iters)``; the explorer calls it with
        ``iters`` = 1, 2, ... 8 from the same start to show each iterate.
    figure : str, optional
        The figure's number in the lesson.
    P, Q : array_like, shape (N, 3), optional
        Body directions (rows) and the same directions measured in the reference
        frame; without them the explorer makes 12 noisy ones. The start sits
        ``start`` rad away from the best rotation (scipy's ``align_vectors``).

    Examples
    --------
    >>> explore_gauss_newton(align_gauss_newton, figure="2b")   # doctest: +SKIP
    """
    if P is None or Q is None:
        rng = np.random.default_rng(8)
        Q = rng.normal(size=(12, 3))
        Q /= np.linalg.norm(Q, axis=1, keepdims=True)
        R_true = Exp([0.4, -0.9, 1.3])
        P = Q @ R_true + rng.normal(scale=0.01, size=Q.shape)
    P, Q = np.asarray(P, dtype=float), np.asarray(Q, dtype=float)
    R_best = Rotation.align_vectors(Q, P)[0].as_matrix()   # the closed-form minimum, as a reference line
    axis = np.array([1.0, -2.0, 2.0]) / 3.0
    max_iters = 8

    def cost(R):
        return np.sum((Q - P @ R.T) ** 2)

    def draw(fig, iteration, start, static=False):
        path, problem = _gauss_newton_path(align_gauss_newton, P, Q, R_best @ Exp(start * axis), max_iters)
        k = min(int(round(iteration)), len(path) - 1)
        ax = fig.add_subplot(2, 1, 1, projection="3d")     # stacked: the lesson column is narrow
        ax2 = fig.add_subplot(2, 1, 2)
        new_3d_axes(f"iteration {k}: $R_{{{k}}}\\,p_i$ against $q_i$", ax=ax, limit=1.15, zoom=0.85,
                    unit="unitless")
        ax.set_xlabel("$x$ (unitless)")
        ax.set_ylabel("$y$ (unitless)")
        ax.set_zlabel("$z$ (unitless)")
        moved = P @ path[k].T
        ax.scatter(*Q.T, color="black", s=22, marker="*", depthshade=False, label="measured $q_i$")
        ax.scatter(*moved.T, color="#D55E00", s=18, marker="o", depthshade=False, label=f"$R_{{{k}}}\\,p_i$")
        for a, b in zip(moved, Q):
            ax.plot(*np.column_stack([a, b]), color="#D55E00", linewidth=0.8, alpha=0.7)
        if static and k > 0:
            first = P @ path[0].T
            ax.scatter(*first.T, color="#56B4E9", s=12, marker="^", depthshade=False, label="$R_0\\,p_i$ (start)")
        draw_point(ax, [0.0, 0.0, 0.0], color="0.3", size=10)
        ax.legend(loc="upper left", fontsize=9)
        finish_3d_axes(ax)

        costs = [cost(R) for R in path]
        ax2.semilogy(range(len(path)), costs, "o-", color="#0072B2", markersize=4,
                     label=f"start {start:.1f} rad away")
        ax2.semilogy([k], [costs[k]], "o", markersize=10, color="#D55E00", markeredgecolor="black")
        ax2.axhline(cost(R_best), color="0.3", linestyle="--", linewidth=1.1, label="closed-form minimum")
        ax2.set_xlim(-0.3, max_iters + 0.3)
        ax2.set_xlabel("Gauss-Newton iteration $k$ (count)")
        ax2.set_ylabel(r"cost $\sum_i |q_i - R_k\,p_i|^2$ (unitless)")
        ax2.set_title(problem or f"cost {costs[k]:.3g} after {k} step(s)", fontsize=10, wrap=True)
        ax2.grid(True, which="major", alpha=0.3)
        ax2.legend(fontsize=9)
        fig.suptitle(_title(figure, "Gauss-Newton on SO(3), one iteration at a time"))

    controls = {"iteration": ("iteration k (count)", 0.0, float(max_iters), 1.0, 0.0),
                "start": ("start angle [rad]", 0.1, 3.0, 0.1, 2.0)}
    return _explore(draw, controls, (7.0, 9.6), {"iteration": 1.0, "start": 2.0},
                    sweep=("iteration", 0.0, float(max_iters), max_iters + 1))
