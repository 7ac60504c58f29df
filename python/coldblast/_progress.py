"""Progress reporting shared by the long calls: progress=True prints to stderr like the CLI
(run/progress.hpp): on a terminal one line rewritten in place at most twice a second; elsewhere (a
log, a notebook's captured stream, a pipe) plain lines without a carriage return, one per 10 % of
the work or per 30 s, with the elapsed time and the ETA. In a Jupyter notebook with tqdm installed,
progress=True draws a tqdm bar instead (``progress="bar"`` asks for one anywhere)."""
import sys
import time


def _duration(seconds):
    if seconds < 120:
        return f"{seconds:.1f} s"
    if seconds < 7200:
        return f"{seconds / 60:.1f} min"
    return f"{seconds / 3600:.1f} h"


class StderrProgress:
    """Callable (done, total) printing ``label: done/total unit (P %), elapsed, ETA``."""

    def __init__(self, label, unit, fmt="{:.0f}", stream=None, terminal=None, clock=time.monotonic):
        self.label, self.unit, self.fmt, self.clock = label, unit, fmt, clock
        self.stream = sys.stderr if stream is None else stream
        if terminal is None:
            isatty = getattr(self.stream, "isatty", None)
            terminal = bool(isatty and isatty())
        self.terminal = terminal
        self.start = self.last = clock()
        self.decile = 0

    def __call__(self, done, total):
        now = self.clock()
        last = done >= total
        if self.terminal:
            if not last and now - self.last < 0.5:
                return
        else:
            decile = int(10 * done / total) if total > 0 else 10
            if not last and decile <= self.decile and now - self.last < 30:
                return
            self.decile = decile
        self.last = now
        elapsed = now - self.start
        eta = elapsed * (total - done) / done if done > 0 else 0.0
        percent = int(100 * done / total) if total > 0 else 100
        text = (f"{self.label}: {self.fmt.format(done)}/{self.fmt.format(total)} {self.unit} ({percent} %), "
                f"{_duration(elapsed)} elapsed, ETA {_duration(eta)}")
        if self.terminal:
            self.stream.write(f"\r{text}   " + ("\n" if last else ""))
        else:
            self.stream.write(text + "\n")
        self.stream.flush()


class BarProgress:
    """Callable (done, total) driving a tqdm bar (tqdm.auto: a widget in a notebook, text elsewhere)."""

    def __init__(self, label, unit, tqdm_class):
        self.label, self.unit, self.tqdm_class, self.bar = label, unit, tqdm_class, None

    def __call__(self, done, total):
        if self.bar is None:
            total = int(total) if float(total).is_integer() else total  # realizations, blocks: whole numbers
            self.bar = self.tqdm_class(total=total, desc=self.label, unit=" " + self.unit)
        self.bar.update((int(done) if float(done).is_integer() else done) - self.bar.n)
        if done >= total:
            self.bar.close()


def in_notebook():
    """True inside a Jupyter kernel (IPython's ZMQ shell), where stderr lines pile up in the cell."""
    ipython = sys.modules.get("IPython")
    shell = ipython.get_ipython() if ipython is not None and hasattr(ipython, "get_ipython") else None
    return shell is not None and type(shell).__name__ == "ZMQInteractiveShell"


def _tqdm():
    try:
        from tqdm.auto import tqdm
    except ImportError:
        return None
    return tqdm


def callback(progress, label, unit, fmt="{:.0f}"):
    """progress: True (a tqdm bar in a notebook where tqdm is installed, else lines on stderr),
    "bar" (a tqdm bar; ValueError without tqdm), "lines" (lines on stderr), False/None (silent) or a
    callable(done, total)."""
    if progress == "bar" or (progress is True and in_notebook() and _tqdm() is not None):
        tqdm = _tqdm()
        if tqdm is None:
            raise ValueError('progress = "bar" needs tqdm (Debian: apt install python3-tqdm; pip install tqdm)')
        return BarProgress(label, unit, tqdm)
    if progress is True or progress == "lines":
        return StderrProgress(label, unit, fmt)
    if not progress:
        return None
    if not callable(progress):
        raise ValueError(f'progress = {progress!r} is not True, False, "bar", "lines" or a callable(done, total)')
    return progress
