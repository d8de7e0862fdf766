"""Run a notebook top to bottom in a fresh kernel (for authors and tests).

Examples
--------
>>> nb = execute_notebook(read_master("solutions/01_frames_and_rotations.ipynb"),
...                       cwd="solutions")                      # doctest: +SKIP
"""

from __future__ import annotations

import base64
import os
from pathlib import Path

import nbformat
from nbclient import NotebookClient


def execute_notebook(
    nb: nbformat.NotebookNode,
    cwd: str | Path,
    timeout: float = 120,
    allow_errors: bool = False,
    inline_figures: bool = True,
) -> nbformat.NotebookNode:
    """Execute ``nb`` (modified in place and returned) with ``cwd`` as working directory.

    ``inline_figures`` keeps matplotlib's inline backend so figures come back
    as PNG outputs; without it the kernel uses Agg and draws nothing (faster).
    """
    env = dict(os.environ)
    env["PYTHONHASHSEED"] = "0"
    if inline_figures:
        env.pop("MPLBACKEND", None)
    else:
        env["MPLBACKEND"] = "Agg"
    client = NotebookClient(
        nb,
        timeout=timeout,
        kernel_name="python3",
        allow_errors=allow_errors,
        resources={"metadata": {"path": str(cwd)}},
        # the kernel's own warnings (e.g. "running over TCP without encryption": it listens on localhost only)
        # would reach the author's terminal after every recording; its errors still do
        extra_arguments=["--IPKernelApp.log_level=ERROR"],
    )
    client.km = client.create_kernel_manager()
    client.km.kernel_spec  # noqa: B018  (resolve the spec before starting)
    client.execute(env=env)
    return nb


def errors(nb: nbformat.NotebookNode) -> list[tuple[int, str, str]]:
    """(cell index, ename, evalue) for every error output of an executed notebook."""
    found = []
    for index, cell in enumerate(nb.cells):
        for output in cell.get("outputs", []):
            if output.get("output_type") == "error":
                found.append((index, output.get("ename"), output.get("evalue")))
    return found


def save_figures(nb: nbformat.NotebookNode, directory: str | Path, prefix: str) -> list[Path]:
    """Write every PNG output of an executed notebook to ``directory``; return the paths."""
    directory = Path(directory)
    directory.mkdir(parents=True, exist_ok=True)
    paths = []
    for index, cell in enumerate(nb.cells):
        for output in cell.get("outputs", []):
            png = output.get("data", {}).get("image/png")
            if png:
                path = directory / f"{prefix}_cell{index:03d}_{len(paths)}.png"
                path.write_bytes(base64.b64decode(png))
                paths.append(path)
    return paths
