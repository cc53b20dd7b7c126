"""`python -m rdisc`: SIGINT and SIGTERM are held back before the rest of rdisc is imported, and
let through once its handlers are in place (`rdisc.cli.main.main`): an early Ctrl-C ends the
run with 130, never a traceback."""

import signal
import sys

if hasattr(signal, "pthread_sigmask"):
    signal.pthread_sigmask(signal.SIG_BLOCK, (signal.SIGINT, signal.SIGTERM))

from rdisc.cli.main import main  # noqa: E402 - after the signals are held back

sys.exit(main())
