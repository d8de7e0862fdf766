"""What decides a grade besides the submission, so that a saved grade is reused only when all of it is unchanged.

:func:`fingerprint_parts` names each ingredient and gives it a short digest
(or a readable value, for the isolation mode and library versions);
:func:`fingerprint` hashes them all. A saved result carries both, so a re-run
can say *why* it re-grades a student (:func:`what_changed`).

Examples
--------
>>> parts = fingerprint_parts(GradingOptions(), course)                  # doctest: +SKIP
>>> sorted(parts)                                                        # doctest: +SKIP
['coursekit', 'grader code', 'grading options', 'hidden suite', 'isolation mode', 'libraries',
 'reference solutions']
>>> what_changed(dict(parts, **{"isolation mode": "limits"}), parts)     # doctest: +SKIP
['isolation mode (limits → namespaces)']
"""

from __future__ import annotations

import hashlib
import json
import os
import platform
from importlib import metadata
from pathlib import Path

from autograder.grading.options import GradingOptions
from autograder.lessons.course import Course
from autograder.sandbox import launcher

GRADER = Path(__file__).resolve().parents[1]  # the autograder package
# Parts whose value is readable as it is (shown as "old → new" when it changes); the others are digests.
READABLE = ("isolation mode", "libraries")
LIBRARIES = ("numpy", "scipy", "nbval", "pytest", "ipykernel")


def _digest_files(files, root):
    digest = hashlib.sha256()
    for path in sorted(files):
        digest.update(str(path.relative_to(root)).encode() + b"\0" + path.read_bytes() + b"\0")
    return digest.hexdigest()[:16]


def _grader_files():
    """The grader's own code: every module except this repository's hidden suite (a part of its course)
    and the mistakes corpus (fixtures for the project's tests and the sample class, never run while grading)."""
    skipped = (GRADER / "hidden", GRADER / "mistakes")
    return [
        p
        for p in GRADER.rglob("*.py")
        if "__pycache__" not in p.parts and not any(parent in skipped for parent in p.parents)
    ]


def _versions():
    found = [f"Python {platform.python_version()}"]
    for name in LIBRARIES:
        try:
            found.append(f"{name} {metadata.version(name)}")
        except metadata.PackageNotFoundError:
            found.append(f"{name} missing")
    return ", ".join(found)


def content_parts(course: Course) -> dict[str, str]:
    """``{ingredient: digest or readable value}`` of what the grader runs: its code, ``course``'s reference
    solutions, coursekit and hidden suite, and the library versions (no options, no isolation mode)."""
    solutions_dir, support, suite = course.solutions, course.support, course.hidden_suite
    hidden = [p for p in suite.rglob("*") if p.is_file() and "__pycache__" not in p.parts]
    return {
        "grader code": _digest_files(_grader_files(), GRADER),
        "reference solutions": _digest_files(solutions_dir.glob("[0-9][0-9]_*.ipynb"), solutions_dir),
        "coursekit": _digest_files([p for p in support.rglob("*.py") if "__pycache__" not in p.parts], support),
        "hidden suite": _digest_files(hidden, suite),
        "libraries": _versions(),
    }


def fingerprint_parts(options: GradingOptions, course: Course) -> dict[str, str]:
    """``{ingredient: digest or readable value}`` for everything besides the submission that decides a grade."""
    content = content_parts(course)
    libraries = content.pop("libraries")
    return {
        **content,
        "grading options": hashlib.sha256(repr(options).encode()).hexdigest()[:16],
        "isolation mode": launcher.isolation()[0],
        "libraries": libraries,
    }


def cache_dir() -> Path:
    """Where this machine remembers what is keyed by a fingerprint (passing canaries, the reference's
    transcripts): ``$AUTOGRADER_CACHE``, else the user's cache folder."""
    explicit = os.environ.get("AUTOGRADER_CACHE")
    if explicit:
        return Path(explicit)
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return Path(base) / "rotations-autograder"


def private_cache_dir() -> Path:
    """:func:`cache_dir`, created readable by this user only (0700; an existing one of this user is made so),
    since what it holds decides grades (a passing canary, the reference's transcripts).

    >>> private_cache_dir().stat().st_mode & 0o777                      # doctest: +SKIP
    448
    """
    folder = cache_dir()
    folder.mkdir(mode=0o700, parents=True, exist_ok=True)
    if folder.stat().st_uid == os.geteuid():
        os.chmod(folder, 0o700)
    return folder


def write_private(path: Path, text: str) -> None:
    """Write ``text`` to ``path`` (in :func:`private_cache_dir`) through a file only this user reads (0600) and a
    rename.

    >>> write_private(cache_dir() / "canary-0123.json", "{}")           # doctest: +SKIP
    """
    private_cache_dir()
    tmp = path.with_name(f".{path.name}.{os.getpid()}.tmp")
    descriptor = os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_TRUNC | os.O_NOFOLLOW | os.O_CLOEXEC, 0o600)
    try:
        os.fchmod(descriptor, 0o600)
        with open(descriptor, "w", encoding="utf-8", closefd=False) as handle:
            handle.write(text)
    finally:
        os.close(descriptor)
    os.replace(tmp, path)


def fingerprint(parts: dict[str, str]) -> str:
    """One digest for all the parts."""
    return hashlib.sha256(json.dumps(parts, sort_keys=True).encode()).hexdigest()[:16]


def what_changed(old_parts: dict[str, str] | None, new_parts: dict[str, str]) -> list[str]:
    """The ingredients that differ, as phrases (``"isolation mode (limits → namespaces)"``)."""
    changed = []
    for name, value in new_parts.items():
        old = (old_parts or {}).get(name)
        if old == value:
            continue
        changed.append(f"{name} ({old} → {value})" if name in READABLE and old else name)
    return changed
