"""The entry of the `rdisc` command (pip's script and `python -m rdisc` alike): importing this
module holds SIGINT and SIGTERM back, before the rest of rdisc is imported, and `main` lets them
through once its handlers are in place (`rdisc.cli.main.main`): an early Ctrl-C ends the run with
130, never a traceback. Held back with the C module: importing `signal` itself takes a few
milliseconds (it imports enum), in which a Ctrl-C would not wait. Nothing else imports this."""

import _signal  # type: ignore[import-not-found]  # the C module, loaded with the interpreter

if hasattr(_signal, "pthread_sigmask"):
    _signal.pthread_sigmask(_signal.SIG_BLOCK, (_signal.SIGINT, _signal.SIGTERM))


def main() -> int:
    """Run the command line (which installs the handlers, then lets the held signals through)."""
    from rdisc.cli.main import main as command_line

    return command_line()
