"""A progress line for long grading runs: count, rate, time left.

It draws as soon as the run starts (0 of N, time left estimated once the
first student is done), only on a terminal (``stream.isatty()``), and stays
quiet otherwise, so logs and CI output are not filled with carriage returns.
"""

from __future__ import annotations

import time
from typing import TextIO


class Progress:
    """``start(total)``, then ``advance(row)`` per finished student, then ``finish()``."""

    def __init__(self, stream: TextIO):
        self.stream = stream
        self.enabled = hasattr(stream, "isatty") and stream.isatty()
        self.total = self.done = 0
        self.started = time.monotonic()
        self.drawn = False

    def start(self, total: int) -> None:
        self.total, self.done, self.started = total, 0, time.monotonic()
        self._draw()

    def _draw(self):
        if self.enabled and self.total:
            self.stream.write(self.line())
            self.stream.flush()
            self.drawn = True

    def line(self) -> str:
        elapsed = time.monotonic() - self.started
        rate = self.done / elapsed if elapsed > 0 else 0.0
        left = (self.total - self.done) / rate if rate > 0 else float("nan")
        width = 24
        filled = int(width * self.done / self.total) if self.total else width
        bar = "█" * filled + "·" * (width - filled)
        eta = f"{left:4.0f} s left" if left == left else "time left: estimated after the first student"
        return f"\r{bar} {self.done}/{self.total} students  {rate * 60:5.1f}/min  {eta}"

    def advance(self, row: tuple | None = None) -> None:
        self.done += 1
        self._draw()

    def finish(self) -> None:
        if self.enabled and self.drawn:
            self.stream.write(self.line() + "\n")
            self.stream.flush()
