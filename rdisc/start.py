"""The entry of the `rdisc` command (pip's script and `python -m rdisc` alike): importing this
module holds SIGINT and SIGTERM back, before the rest of rdisc is imported, and `main` lets them
through once its handlers are in place (`rdisc.cli.main.main`): an early Ctrl-C ends the run with
130, never a traceback. Held back with the C module: importing `signal` itself takes a few
milliseconds (it imports enum), in which a Ctrl-C would not wait. Nothing else imports this."""

import _signal  # type: ignore[import-not-found]  # the C module, loaded with the interpreter

if hasattr(_signal, "pthread_sigmask"):
    _signal.pthread_sigmask(_signal.SIG_BLOCK, (_signal.SIGINT, _signal.SIGTERM))


# Verbs that only read files and write their output: their process ends without the interpreter's
# teardown, as mypy's does. Freeing every module, class and object one by one is about a fifth of a
# cold `rdisc check`; the system takes the memory back at once, and they leave nothing to close.
ENDED_AT_ONCE = frozenset({"check"})


def main() -> int:
    """Run the command line (which installs the handlers, then lets the held signals through).
    The cyclic collector waits while rdisc is imported (its passes there find nothing to free),
    and for the whole of a verb ended at once: nothing is freed at its end, and a pass after a
    check, over every object the check made, is a tenth of a check of 100,000 lines."""
    import gc
    import sys

    gc.disable()
    from rdisc.cli.main import main as command_line
    from rdisc.cli.main import verb_named

    ended_at_once = verb_named(sys.argv[1:]) in ENDED_AT_ONCE
    if not ended_at_once:
        gc.enable()
    status = command_line()
    if ended_at_once:
        end_at_once(status)
    return status


def end_at_once(status: int) -> None:
    """Flush what was written and end the process with `status`, skipping the teardown."""
    import os
    import sys

    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):  # a closed pipe, or a closed stream: nothing more can be written
            pass
    os._exit(status)
