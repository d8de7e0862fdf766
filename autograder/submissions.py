"""Find students and their notebooks in a folder of submissions.

Two layouts are understood:

- one folder per student: ``PATH/<student_id>/01_frames_and_rotations.ipynb``;
- nbgrader's: ``PATH/submitted/<student_id>/<assignment>/01_....ipynb`` (PATH may
  also be the ``submitted`` folder itself, or an nbgrader course root).

A notebook is matched by its file name, or else by its two-digit lesson
prefix (``01_my_copy.ipynb``). Symbolic links are never followed.
"""

import hashlib
import os
from pathlib import Path

MAX_DEPTH = 2


def student_folders(path):
    """Sorted ``[(student_id, folder)]`` under ``path`` (see the module docstring)."""
    path = Path(path)
    if (path / "submitted").is_dir() and not (path / "submitted").is_symlink():
        path = path / "submitted"
    found = []
    for entry in sorted(path.iterdir()):
        if entry.is_dir() and not entry.is_symlink() and not entry.name.startswith("."):
            found.append((entry.name, entry))
    return found


def notebooks_in(folder):
    """Regular ``.ipynb`` files and links to them up to two levels down, as paths."""
    folder = Path(folder)
    found = []
    for root, dirs, files in os.walk(folder, followlinks=False):
        depth = len(Path(root).relative_to(folder).parts)
        dirs[:] = sorted(d for d in dirs if not d.startswith(".") and depth < MAX_DEPTH)
        for name in sorted(files):
            if name.endswith(".ipynb") and not name.startswith("."):
                found.append(Path(root) / name)
    return found


def find_notebook(folder, lesson, notebooks=None):
    """The student's notebook for ``lesson`` (exact name first, then NN_ prefix), or None."""
    notebooks = notebooks_in(folder) if notebooks is None else notebooks
    exact = [p for p in notebooks if p.name == lesson.filename]
    if exact:
        return exact[0]
    prefixed = [p for p in notebooks if p.name.startswith(lesson.number + "_")]
    return prefixed[0] if prefixed else None


def submission_hash(folder):
    """SHA-256 over the names and bytes of every notebook of a student (links by their target text)."""
    digest = hashlib.sha256()
    folder = Path(folder)
    for path in notebooks_in(folder):
        digest.update(str(path.relative_to(folder)).encode("utf-8") + b"\0")
        if path.is_symlink():
            digest.update(b"link:" + os.readlink(path).encode("utf-8", "replace"))
        else:
            try:
                with open(path, "rb") as handle:
                    for block in iter(lambda: handle.read(1 << 20), b""):
                        digest.update(block)
            except OSError as error:
                digest.update(f"unreadable:{error.errno}".encode())
        digest.update(b"\0")
    return digest.hexdigest()
