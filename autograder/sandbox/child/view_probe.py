"""What can a sandbox see? Run inside one by the canary (``grading/canary.py: check_sandbox_view``).

Reads ``/sandbox/view_secrets.json``: ``paths`` (host paths that must not exist inside: the hidden suite,
the masters, the submissions, the output, the cache, the grader's checkout) and ``sizes`` (the sizes of
secret files: the hidden suite's, the masters'...). Walks everything visible (not ``/proc``, ``/sys``,
``/dev``), bounded, never following a link, and prints one JSON line: for each secret path that exists
inside, its entries (up to 50); every regular file whose size is a secret's size, with its SHA-256 (the
grader compares digests, so the secrets' own digests never enter the sandbox); how many entries it saw.
Imports only the standard library.

Example (inside a sandbox)::

    python -I /sandbox/view_probe.py /sandbox/view_secrets.json
    {"present": {"/work/main": [".venv"]}, "candidates": [], "entries": 21873, "truncated": false}
"""

from __future__ import annotations

import hashlib
import json
import os
import stat
import sys

SKIP = ("/proc", "/sys", "/dev")
MAX_ENTRIES = 400_000
MAX_CANDIDATES = 2_000


def _digest(path: str) -> str:
    digest = hashlib.sha256()
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NOFOLLOW | os.O_NONBLOCK)
    except OSError:
        return ""
    try:
        with os.fdopen(fd, "rb") as file:
            for block in iter(lambda: file.read(1 << 20), b""):
                digest.update(block)
    except OSError:
        return ""
    return digest.hexdigest()


def main(spec_path: str) -> dict:
    with open(spec_path, encoding="utf-8") as file:
        spec = json.load(file)
    own = {os.path.abspath(spec_path), os.path.abspath(__file__)}
    present = {}
    for path in spec.get("paths", []):
        if os.path.lexists(path):
            try:
                present[path] = sorted(os.listdir(path))[:50] if os.path.isdir(path) else []
            except OSError as error:
                present[path] = [f"<{type(error).__name__}>"]
    sizes = {int(size) for size in spec.get("sizes", [])}
    candidates, entries, truncated = [], 0, False
    todo = ["/"]
    while todo and not truncated:
        folder = todo.pop()
        try:
            with os.scandir(folder) as listing:
                for entry in listing:
                    entries += 1
                    if entries > MAX_ENTRIES:
                        truncated = True
                        break
                    path = entry.path
                    try:
                        info = entry.stat(follow_symlinks=False)
                    except OSError:
                        continue
                    if stat.S_ISDIR(info.st_mode):
                        if path not in SKIP:
                            todo.append(path)
                    elif stat.S_ISREG(info.st_mode) and info.st_size in sizes and path not in own:
                        if len(candidates) < MAX_CANDIDATES:
                            candidates.append([path, info.st_size, _digest(path)])
        except OSError:
            continue
    return {"present": present, "candidates": candidates, "entries": entries, "truncated": truncated}


if __name__ == "__main__":
    print(json.dumps(main(sys.argv[1])), flush=True)
