"""SIGTERM during a long call (a batch system's time limit, `kill`, `scancel`) stops it like Ctrl-C:
the library finishes the current realization, keeps every finished one in out/checkpoint, and the
call raises SystemExit(143), the CLI's exit code for SIGTERM. Without this, Python's default SIGTERM
ends the process at once and the realizations in progress since the last save are lost."""
import contextlib
import signal
import threading


@contextlib.contextmanager
def sigterm_stops():
    """Within the block, SIGTERM raises SystemExit(143) in the main thread (where the long calls poll
    for signals every 0.1 s); a handler the program installed itself is left alone."""
    if threading.current_thread() is not threading.main_thread() or \
            signal.getsignal(signal.SIGTERM) is not signal.SIG_DFL:
        yield
        return

    def stop(signum, frame):
        raise SystemExit(128 + signum)

    signal.signal(signal.SIGTERM, stop)
    try:
        yield
    finally:
        signal.signal(signal.SIGTERM, signal.SIG_DFL)
