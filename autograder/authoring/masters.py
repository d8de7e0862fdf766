"""Helpers for writing lesson masters from a script or a console.

Example
-------
>>> from autograder.lessons import cells
>>> nb = new_lesson([cells.markdown("# Lesson 99 — Demo"), cells.setup("import numpy as np")])
>>> save_master(nb, "/tmp/99_demo.ipynb")   # doctest: +SKIP

The saved file is normalised (see :func:`autograder.authoring.release.normalize_master`),
so what you save is exactly what ``python -m autograder release`` keeps.
"""

from __future__ import annotations

from pathlib import Path

import nbformat

from autograder.authoring.release import normalize_master
from autograder.lessons.notebook_files import canonical_text, write_if_changed

KERNELSPEC = {"display_name": "Python 3 (ipykernel)", "language": "python", "name": "python3"}


def new_lesson(cell_list: list[nbformat.NotebookNode]) -> nbformat.NotebookNode:
    """A version-4.5 notebook holding ``cell_list``, with the course's kernel metadata."""
    nb = nbformat.v4.new_notebook()
    nb.nbformat_minor = 5
    nb.metadata = {"kernelspec": dict(KERNELSPEC), "language_info": {"name": "python"}}
    nb.cells = list(cell_list)
    return nb


def save_master(nb: nbformat.NotebookNode, path: str | Path) -> bool:
    """Normalise ``nb`` and write it to ``path``; return True if the file changed."""
    return write_if_changed(path, canonical_text(normalize_master(nb)))
