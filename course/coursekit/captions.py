"""A figure's caption as words a person (or a screen reader) reads: no TeX source.

Titles are drawn with matplotlib's mathtext (``$\\mathbf{R}_z(\\delta)$``); as
alt text of a picture in the book, or as the accessible name of a live figure
in JupyterLab, the same title must read "R_z(δ)", not the TeX that draws it.
:func:`readable_text` turns mathtext into plain Unicode text, and
:func:`figure_caption` gives a figure's caption that way.

Examples
--------
>>> readable_text(r"Figure 3. The family $R_z(\\delta)\\,R_y(\\pi/2)$, $\\alpha$ = 0.3 rad")
'Figure 3. The family R_z(δ) R_y(π/2), α = 0.3 rad'
>>> readable_text(r"error $\\|\\mathbf{R}^\\top\\mathbf{R} - I\\|$ at $h = 10^{-15}$")
'error ‖RᵀR - I‖ at h = 10⁻¹⁵'
"""

import re

__all__ = ["readable_text", "figure_caption"]

GREEK = {name: chr(code) for name, code in [
    ("alpha", 0x3B1), ("beta", 0x3B2), ("gamma", 0x3B3), ("delta", 0x3B4), ("epsilon", 0x3B5), ("varepsilon", 0x3B5),
    ("zeta", 0x3B6), ("eta", 0x3B7), ("theta", 0x3B8), ("vartheta", 0x3D1), ("iota", 0x3B9), ("kappa", 0x3BA),
    ("lambda", 0x3BB), ("mu", 0x3BC), ("nu", 0x3BD), ("xi", 0x3BE), ("pi", 0x3C0), ("rho", 0x3C1),
    ("sigma", 0x3C3), ("tau", 0x3C4), ("upsilon", 0x3C5), ("phi", 0x3C6), ("varphi", 0x3C6), ("chi", 0x3C7),
    ("psi", 0x3C8), ("omega", 0x3C9), ("Gamma", 0x393), ("Delta", 0x394), ("Theta", 0x398), ("Lambda", 0x39B),
    ("Xi", 0x39E), ("Pi", 0x3A0), ("Sigma", 0x3A3), ("Phi", 0x3A6), ("Psi", 0x3A8), ("Omega", 0x3A9)]}
SYMBOLS = {"times": "×", "cdot": "·", "top": "ᵀ", "|": "‖", "to": "→", "rightarrow": "→", "approx": "≈",
           "leq": "≤", "le": "≤", "geq": "≥", "ge": "≥", "neq": "≠", "infty": "∞", "sqrt": "√", "circ": "°",
           "partial": "∂", "sum": "∑", "prod": "∏", "int": "∫", "boxplus": "⊞", "boxminus": "⊟", "otimes": "⊗",
           "pm": "±", "ldots": "…", "dots": "…",
           "cdots": "…", "in": "∈", "sim": "∼", "propto": "∝", "nabla": "∇", "degree": "°", "prime": "′",
           "langle": "⟨", "rangle": "⟩", "lvert": "|", "rvert": "|", "lVert": "‖", "rVert": "‖", "%": "%",
           "{": "{", "}": "}", "$": "$", "_": "_", "#": "#", "&": "&"}
SPACES = {",": " ", ";": " ", ":": " ", "!": "", " ": " ", "quad": " ", "qquad": " "}
SUPERSCRIPT = dict(zip("0123456789+-=()niT", "⁰¹²³⁴⁵⁶⁷⁸⁹⁺⁻⁼⁽⁾ⁿⁱᵀ"))
SUBSCRIPT = dict(zip("0123456789+-=()", "₀₁₂₃₄₅₆₇₈₉₊₋₌₍₎"))
# commands whose argument is shown as it is (a font or a function name)
_ARGUMENT_AS_IS = re.compile(r"\\(?:mathbf|mathrm|mathit|mathsf|mathtt|mathcal|mathfrak|boldsymbol|bf|rm|it|"
                             r"operatorname|text|textrm|textbf|mathbb|vec)\s*\{([^{}]*)\}")
# accents on one letter: a combining mark after it (R̂, ẋ)
ACCENTS = {"hat": "\u0302", "widehat": "\u0302", "bar": "\u0304", "tilde": "\u0303", "dot": "\u0307",
           "ddot": "\u0308"}
_ACCENT = re.compile(r"\\(" + "|".join(ACCENTS) + r")\s*\{([^{}]*)\}")
_FRACTION = re.compile(r"\\[dt]?frac\s*\{([^{}]*)\}\s*\{([^{}]*)\}")
GAP = "\x01"  # ends a command name where a font's braces were: \top\mathbf{R} is "ᵀR", not a command "topR"
_COMMAND = re.compile(r"\\([A-Za-z]+|.)")
_SCRIPT = re.compile(r"([\^_])(\{([^{}]*)\}|\\[A-Za-z]+|.)")


def _script(match):
    mark, body = match.group(1), match.group(3) if match.group(3) is not None else match.group(2)
    table = SUPERSCRIPT if mark == "^" else SUBSCRIPT
    if body and all(ch in table for ch in body):
        return "".join(table[ch] for ch in body)
    if body in ("ᵀ", "′", "×"):                          # R^\top, f^\prime, [ω]_\times
        return body
    return f"{mark}{body}" if len(body) == 1 else f"{mark}({body})"


def _math(tex):
    """One mathtext formula (between dollars) as plain text."""
    text = tex
    for _ in range(3):                                    # nested fonts: \hat{\mathbf{x}}
        text = _ARGUMENT_AS_IS.sub(GAP + r"\1" + GAP, text)
        text = _ACCENT.sub(lambda m: GAP + m.group(2) + (ACCENTS[m.group(1)] if len(m.group(2).strip(GAP)) == 1
                                                         else "") + GAP, text)
        text = _FRACTION.sub(lambda m: f"{GAP}{_group(m.group(1))}/{_group(m.group(2))}{GAP}", text)
    text = re.sub(r"\\(?:left|right|big|Big|bigg|Bigg)\b\s*", "", text)

    def command(match):
        name = match.group(1)
        if name in GREEK:
            return GREEK[name]
        if name in SYMBOLS:
            return SYMBOLS[name]
        if name in SPACES:
            return SPACES[name]
        return name                                       # \exp, \log, \sin, \det, \max: the word itself

    text = _COMMAND.sub(command, text)
    text = _SCRIPT.sub(_script, text)
    return text.replace("{", "").replace("}", "").replace(GAP, "")


def _group(part):
    """A fraction's numerator or denominator: in parentheses when it is more than one symbol."""
    bare = part.strip().strip(GAP)
    return bare if re.fullmatch(r"\\[A-Za-z]+|\w?|\d+", bare) else f"({bare})"


def readable_text(text):
    """``text`` with every mathtext formula (``$...$``) written as plain Unicode, and spaces collapsed.

    Parameters
    ----------
    text : str
        A title as matplotlib draws it, e.g. ``"$\\theta$ from 0 to $2\\pi$"``.

    Returns
    -------
    str
        E.g. ``"θ from 0 to 2π"``: no dollar sign, backslash command or brace of TeX is left.

    Examples
    --------
    >>> readable_text(r"A steady spin $R(t) = \\exp(t\\,[\\omega]_\\times)$")
    'A steady spin R(t) = exp(t [ω]×)'
    """
    text = re.sub(r"(?<!\\)\$([^$]*)(?<!\\)\$", lambda m: _math(m.group(1)), str(text))
    text = text.replace("\\$", "$")
    return " ".join(text.split())


def figure_caption(fig):
    """A figure's caption as readable text: its suptitle, then its axes' titles ("" when it has none).

    A live figure's title may change (an explorer's "Gimbal at pitch 88.5°"):
    the caption says it, so the alt text and the accessible name tell what the
    figure shows now, not only what it is.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    str
        E.g. ``"Figure 5. Turn the gimbal — Gimbal at yaw 30°, pitch 88.5°"``: the titles,
        :func:`readable_text`, joined by " — ".
    """
    suptitle = getattr(fig, "_suptitle", None)
    texts = [suptitle.get_text()] if suptitle is not None else []
    texts += [ax.get_title() for ax in fig.axes]
    readable = [readable_text(t) for t in texts if t and t.strip()]
    return " — ".join(dict.fromkeys(readable))
