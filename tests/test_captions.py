"""Captions as words: what a reader of the book (alt text) and a screen reader in the lab (a live figure's
accessible name) get from a figure's titles, with no TeX source left in them."""

import re

import matplotlib

matplotlib.use("agg")
import matplotlib.pyplot as plt  # noqa: E402
import pytest  # noqa: E402

from coursekit.captions import figure_caption, readable_text  # noqa: E402
from coursekit.plotting import name_live_figure, name_live_figure_when_drawn, name_open_figures  # noqa: E402

# ipympl 0.10's toolbar passes traitlets an argument it deprecates (not ours to mend)
pytestmark = pytest.mark.filterwarnings("ignore:Passing unrecognized arguments:DeprecationWarning")

TEX_LEFT = re.compile(r"[$\\{}]|\b(mathbf|mathrm|frac|boldsymbol|theta|delta|times)\b")


@pytest.mark.parametrize(
    "tex, words",
    [
        (
            r"Figure 3. The family $R_z(\delta)\,R_y(\pi/2)\,R_x(\alpha + \delta)$, $\alpha$ = 0.3 rad",
            "Figure 3. The family R_z(δ) R_y(π/2) R_x(α + δ), α = 0.3 rad",
        ),
        (r"A steady spin $R(t) = \exp(t\,[\omega]_\times)$", "A steady spin R(t) = exp(t [ω]×)"),
        (r"$\|\mathbf{R}^\top\mathbf{R} - I\|$ at $h = 10^{-15}$", "‖RᵀR - I‖ at h = 10⁻¹⁵"),
        (r"columns $r_1, r_2, r_3$", "columns r₁, r₂, r₃"),
        (r"$\frac{\pi}{2} - \varepsilon$ and $\frac{a+b}{2}$", "π/2 - ε and (a+b)/2"),
        (r"$\mathrm{Exp}(\theta\mathbf{u})$, $\hat{\mathbf{R}}$, $x_{\mathrm{body}}$", "Exp(θu), R̂, x_(body)"),
        ("no math: 5% of \\$3, pitch 88.5°", "no math: 5% of $3, pitch 88.5°"),
    ],
)
def test_readable_text(tex, words):
    assert readable_text(tex) == words
    assert not TEX_LEFT.search(readable_text(tex).replace("$3", ""))


def test_a_caption_is_the_suptitle_then_the_titles():
    fig, (left, right) = plt.subplots(1, 2)
    assert figure_caption(fig) == ""
    left.set_title(r"near $\theta = 0$")
    right.set_title(r"near $\theta = \pi$")
    fig.suptitle("Figure 3. Accuracy\nof the logarithm")
    assert figure_caption(fig) == "Figure 3. Accuracy of the logarithm — near θ = 0 — near θ = π"
    plt.close(fig)


def _live(fig, number=2):
    """Give ``fig`` a real ipympl canvas and manager (widget comms have no kernel here: messages go nowhere)."""
    from ipympl.backend_nbagg import Canvas, FigureManager

    FigureManager(Canvas(fig), number)
    return fig


def test_a_live_figure_is_renamed_by_its_title_each_time_it_is_drawn():
    fig = plt.figure()
    assert name_live_figure(fig) is fig  # a picture: nothing to name
    name_live_figure_when_drawn(_live(fig))
    fig.suptitle(r"Figure 2b. Gimbal at pitch $88.5°$")
    fig.canvas.draw()
    assert fig.canvas._figure_label == "Figure 2b. Gimbal at pitch 88.5°"
    fig.suptitle("Figure 2b. Gimbal at pitch 90°")
    fig.canvas.draw()
    assert fig.canvas._figure_label == "Figure 2b. Gimbal at pitch 90°"
    plt.close("all")


def test_a_refresh_from_the_page_keeps_the_caption():
    """The page asks for a refresh after each resize, and a refresh re-sends the figure's window title;
    with no redraw after it (one already pending), the name must survive it. A browser run of lesson 09
    once ended with its Figure 2 named "Figure 2" that way."""
    fig, ax = plt.subplots()
    ax.set_title("Figure 2. q and −q are one rotation")
    name_live_figure(_live(fig))
    fig.canvas.handle_refresh({})
    assert fig.canvas._figure_label == "Figure 2. q and −q are one rotation"
    plt.close("all")


def test_a_cell_that_ends_names_its_figures_before_any_draw(monkeypatch):
    """The post_execute hook: a figure the kernel has not drawn yet (the page's draw request still
    queued) is named when its cell ends."""
    from matplotlib._pylab_helpers import Gcf

    fig, ax = plt.subplots()
    ax.set_title(r"Figure 5. Gauss-Newton on $SE(3)$")
    monkeypatch.setattr(Gcf, "figs", {5: _live(fig, 5).canvas.manager})  # open, as pyplot keeps a shown figure
    name_open_figures()
    assert fig.canvas._figure_label == "Figure 5. Gauss-Newton on SE(3)"
