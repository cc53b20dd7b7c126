"""`python -m rdisc`: SIGINT and SIGTERM are held back before the rest of rdisc is imported, and
let through once its handlers are in place (`rdisc.cli.main.main`): an early Ctrl-C ends the
run with 130, never a traceback. Held back with the C module: importing `signal` itself takes a
few milliseconds (it imports enum), in which a Ctrl-C would not wait."""

import _signal  # type: ignore[import-not-found]  # the C module, loaded with the interpreter
import sys

if hasattr(_signal, "pthread_sigmask"):
    _signal.pthread_sigmask(_signal.SIG_BLOCK, (_signal.SIGINT, _signal.SIGTERM))

from rdisc.cli.main import main

sys.exit(main())
