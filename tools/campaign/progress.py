"""Progress lines: cases done of all, time elapsed, time left.

The time left is the pending cases times the mean time between finished
cases since the driver started (all partitions together)."""
import time


def hms(seconds):
    s = int(round(seconds))
    return f"{s // 3600}:{s // 60 % 60:02d}:{s % 60:02d}"


class Progress:
    def __init__(self, total, done, say):
        self.total, self.done, self.say = total, done, say
        self.start, self.finished = time.time(), 0

    def case_done(self, key, row, results):
        self.done += 1
        self.finished += 1
        elapsed = time.time() - self.start
        left = (self.total - self.done) * elapsed / self.finished
        values = " ".join(f"{r}={row[r]}" for r in results)
        w = len(str(self.total))
        self.say(f"[{self.done:{w}d}/{self.total}] {key}: {values}   "
                 f"elapsed {hms(elapsed)}, left ~{hms(left)}")
