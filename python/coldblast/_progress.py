"""Progress reporting shared by the long calls: progress=True prints to stderr like the CLI."""
import sys
import time


class StderrProgress:
    """Callable (done, total) printing ``label: done/total unit, elapsed, ETA`` at most twice a second."""

    def __init__(self, label, unit, fmt="{:.0f}"):
        self.label, self.unit, self.fmt = label, unit, fmt
        self.start = self.last = time.monotonic()

    def __call__(self, done, total):
        now = time.monotonic()
        if done < total and now - self.last < 0.5:
            return
        self.last = now
        elapsed = now - self.start
        eta = elapsed * (total - done) / done if done > 0 else 0.0
        sys.stderr.write(f"\r{self.label}: {self.fmt.format(done)}/{self.fmt.format(total)} {self.unit}, "
                         f"{elapsed:.1f} s elapsed, ETA {eta:.1f} s   ")
        if done >= total:
            sys.stderr.write("\n")
        sys.stderr.flush()


def callback(progress, label, unit, fmt="{:.0f}"):
    """progress: True (stderr), False/None (silent) or a callable(done, total)."""
    if progress is True:
        return StderrProgress(label, unit, fmt)
    if not progress:
        return None
    if not callable(progress):
        raise ValueError(f"progress = {progress!r} is not True, False or a callable(done, total)")
    return progress
