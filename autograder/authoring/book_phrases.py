"""The reader's wording: what the lab says to a student, said to a reader of the book.

In the lab a student runs *their own* answers, so the masters say "with your
``boxminus``", "Your numerical Jacobian against two analytic ones", "before you
run the check cell". The book runs the reference answers and has no check
cells, so :func:`reader_phrasing` rewrites those phrases when the book is built:
"with the reference ``boxminus``", "The reference numerical Jacobian against
two analytic ones", and the check-cell clause is dropped. Phrases that speak to
the reader as a person stay ("your right hand", "in your head", "Your turn").

Each rule is a regular expression and its replacement; a capital "Your" at the
start of a sentence gives a capital "The". ``tests/test_book.py`` reads the
built book for :data:`LAB_ONLY_PHRASES`.

Examples
--------
>>> reader_phrasing("Your `quat_boxplus` agrees with the matrix version.")
'The reference `quat_boxplus` agrees with the matrix version.'
>>> reader_phrasing("Test it on pairs you can see in your head before you run the check cell.")
'Test it on pairs you can see in your head.'
"""

from __future__ import annotations

import re

__all__ = ["reader_phrasing", "LAB_ONLY_PHRASES"]

# What a reader of the book must never read (case-insensitive), checked on every page of the built book.
LAB_ONLY_PHRASES = (
    "your log_so3",
    "your answer",
    "your function",
    "your solver",
    "your numerical",
    "your formula",
    "your recipe",
    "your product",
    "your adjoint",
    "your result",
    "your Exercise",
    "your lesson-0",
    "your own numerical",
    "run the check cell",
    "the grader",
)

# The nouns that name a student's answer (the book shows the reference's instead).
_ANSWERS = (
    r"(?:functions?|rotations|product|robust solver|solver|formula|numerical Jacobian|"
    r"Jacobian|adjoint|recipe|result|iterations|lock threshold|matrix|round trip)"
)

_RULES = [
    # instructions of an exercise statement: the reader reads them about "the" function
    (r"\bDo not call your\b", "Do not call"),
    (r"\b(inside|verify) your\b", r"\1 the"),
    (r"\bTest your function\b", "Try the function"),
    (r",? so it works whatever state your answer is in", ""),
    (r"\*([Yy])our\* ", r"\1he reference "),
    # an exercise statement's requirement: "Your function must ..." is "The function must ..."
    (r"\b([Yy])our (function|answer|method) (must|should|do)\b", r"\1he \2 \3"),
    (r"\b([Yy])our answer\b", r"\1he reference answer"),
    # an earlier lesson's answers: the book's lessons never depend on them either
    (r"\b([Yy])our (lesson-\d\d) (answers|code)\b", r"\1he \2 exercises"),
    (r"\b([Yy])our (Exercise \d+)\b", r"\1he reference answer of \2"),
    (r"\b([Yy])our (two|three) (functions|rotations)\b", r"\1he \2 reference \3"),
    # "your `name`", "your own `name`", "your $\mathbf J_r$": the reference's answer
    (r"\b([Yy])our (?:own )?(`[^`\n]+`|\$[^$\n]+\$)", r"\1he reference \2"),
    (rf"\b([Yy])our ({_ANSWERS})\b", r"\1he reference \2"),
    # the lab's tools: the reader has no check cell and no grader
    (r",? before you run the check cell", ""),
    (r"\bthe grader accepts\b", "the checks accept"),
    (r"\(the grader tests each exercise on its own\)", "(each exercise stands on its own)"),
]
_COMPILED = [(re.compile(pattern), replacement) for pattern, replacement in _RULES]


def _capital(match, replacement):
    text = match.expand(replacement)
    # the rules write "\1he" for "The"/"the": the captured Y/y decides the capital
    return re.sub(r"^[Yy]he", lambda m: "The" if m.group(0)[0] == "Y" else "the", text)


def reader_phrasing(text: str) -> str:
    """``text`` (markdown, or a code cell's source) as the reader's edition says it.

    Parameters
    ----------
    text : str

    Returns
    -------
    str
        The text with the lab's phrases rewritten (:data:`_RULES`).

    Examples
    --------
    >>> reader_phrasing("With your `boxminus` and your three functions")
    'With the reference `boxminus` and the three reference functions'
    """
    for pattern, replacement in _COMPILED:
        text = pattern.sub(lambda match, r=replacement: _capital(match, r), text)
    return text
