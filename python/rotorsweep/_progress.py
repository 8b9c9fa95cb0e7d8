"""The progress line of rotorsweep.run on sys.stderr: members done / total, rate, time left; redrawn
in place on a terminal, one line every 10 s otherwise (like the command line's)."""

import sys
import time


class ProgressLine:
    def __init__(self, total, enabled):
        self.total = total
        self.enabled = enabled
        self.terminal = enabled and sys.stderr.isatty()
        self.start = self.last = time.monotonic()
        self.width = 0

    def update(self, done):
        if not self.enabled:
            return
        now = time.monotonic()
        if now - self.last < (0.25 if self.terminal else 10.0):
            return
        self.last = now
        elapsed = now - self.start
        rate = done / elapsed if elapsed > 0 else 0.0
        left = f", {(self.total - done) / rate:.0f} s left" if rate > 0 else ""
        text = f"{done}/{self.total} members ({100 * done / max(self.total, 1):.1f} %, {rate:.1f}/s{left})"
        if self.terminal:
            sys.stderr.write("\r" + text.ljust(self.width))
            self.width = len(text)
        else:
            sys.stderr.write(text + "\n")
        sys.stderr.flush()

    def finish(self):
        if self.terminal and self.width:
            sys.stderr.write("\r" + " " * self.width + "\r")
            sys.stderr.flush()
