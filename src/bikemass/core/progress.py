"""A dependency-free progress bar on stderr for long commands (silent when stderr is not a terminal)."""

import sys
import time


class Progress:
    """``with Progress(total, "study") as bar: ... bar.step("label")``."""

    def __init__(self, total, title, stream=None, width=30, enabled=True):
        self.total, self.title, self.width = max(int(total), 1), title, width
        self.stream = stream or sys.stderr
        self.done = 0
        self.enabled = enabled and self.stream.isatty()
        self.start = time.perf_counter()

    def __enter__(self):
        self._draw("")
        return self

    def step(self, label="", n=1):
        """Advance by ``n`` and show ``label`` (what is being worked on)."""
        self.done = min(self.done + n, self.total)
        self._draw(label)

    def _draw(self, label):
        if not self.enabled:
            return
        filled = int(self.width * self.done / self.total)
        elapsed = time.perf_counter() - self.start
        line = (f"\r{self.title} [{'#' * filled}{'.' * (self.width - filled)}] "
                f"{self.done}/{self.total} {elapsed:5.1f}s {label}")
        self.stream.write(line[:120].ljust(120))
        self.stream.flush()

    def __exit__(self, *exc):
        if self.enabled:
            self.stream.write("\n")
            self.stream.flush()
        return False
