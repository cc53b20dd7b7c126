"""`rdisc VERB ...`: one module per verb, each with add_parser() and run(args) -> exit code.

A verb's module is imported only when that verb is asked for: `rdisc check` need not load
the runtime, asyncio or the console to start (`rdisc --help` loads them all to list them).
"""

from __future__ import annotations

import argparse
import contextlib
import signal
import sys
from types import ModuleType

from rdisc import TYPE_CHECKING, __version__

if TYPE_CHECKING:
    from typing import Any

# Each verb and its module in rdisc.cli, in the order `rdisc --help` lists them. Only these
# names are ever imported.
VERBS = {
    "check": "check", "build": "build", "import": "import_", "explain": "explain", "run": "run", "sim": "sim",
    "replay": "replay", "console": "console", "emit-python": "emit_python", "emit-ros": "emit_ros",
    "emit-ros2": "emit_ros2",
    "emit-urdf": "emit_urdf", "emit-sdf": "emit_sdf", "emit-mjcf": "emit_mjcf", "dump": "dump", "graph": "graph",
    "decode": "decode", "lsp": "lsp", "fmt": "fmt", "adapters": "adapters",
}  # fmt: skip
EXIT_INTERNAL = 3


def _module(verb: str) -> ModuleType:
    """The verb's module, imported with `__import__`: the `importlib` package is a few percent of
    a cold `rdisc check` (`python -m` imports it anyway, the `rdisc` script does not)."""
    name = f"rdisc.cli.{VERBS[verb]}"
    __import__(name)
    return sys.modules[name]


def _tokens(text: str) -> int:
    try:
        value = int(text.replace("_", "").replace(",", ""))
    except ValueError:
        raise argparse.ArgumentTypeError(f"not a number of tokens: {text!r}") from None
    if value < 1:
        raise argparse.ArgumentTypeError(f"the budget must be at least one token, not {value}")
    return value


def verb_named(argv: list[str]) -> str | None:
    """The verb `argv` names: its first word that is not an option."""
    return next((a for a in argv if not a.startswith("-")), None)


class _Formatter(argparse.HelpFormatter):
    """argparse's help, laid out to the terminal's width, asked when help or usage is written:
    argparse makes a formatter for each argument added (to test its metavar), and its own asks
    the width each time, importing shutil (with bz2 and lzma), about 4 ms of a cold check."""

    def __init__(self, prog: str) -> None:
        super().__init__(prog, width=80)  # the metavar test reads no width

    def format_help(self) -> str:
        measured = argparse.HelpFormatter(self._prog)  # the width and help column argparse would use
        self._width, self._max_help_position = measured._width, measured._max_help_position
        return super().format_help()


class _Parser(argparse.ArgumentParser):
    """A parser whose help is `_Formatter`'s; the verbs' parsers are made of this class too."""

    def __init__(self, **options: Any) -> None:
        options.setdefault("formatter_class", _Formatter)
        super().__init__(**options)


def parser(argv: list[str] | None = None) -> argparse.ArgumentParser:
    """The command line's parser: of the verb `argv` names, or of every verb."""
    p = _Parser(
        prog="rdisc",
        description="The RDIS toolchain: check robot device descriptions and turn them into what frameworks use.",
    )
    p.add_argument("--version", action="version", version=f"rdisc {__version__}")
    p.add_argument("--debug", action="store_true", help="show the Python traceback of an internal error")
    verbs = p.add_subparsers(dest="verb", metavar="VERB", required=True, prog="rdisc")  # not laid out: no width asked
    named = verb_named(argv or [])
    for verb in [named] if named in VERBS else VERBS:
        _module(verb).add_parser(verbs)
        if verb != "explain":  # every other verb reads a description (and has imported rdisc.compile)
            from rdisc.compile import MAX_TOKENS

            verbs.choices[verb].add_argument(
                "--max-tokens", type=_tokens, metavar="N",
                help=f"read a description of up to N tokens with its imports (default {MAX_TOKENS:,}): for large,"
                " generated descriptions you trust; checking takes time in proportion to them")
    return p


def main(argv: list[str] | None = None) -> int:
    """The command line: SIGINT and SIGTERM are held back from the first instant until the engine's
    handlers are in place (`engine.command_line`), so a signal that comes while rdisc is still
    starting ends it with 130 or 143 and no traceback; the mask found is restored after."""
    held = hold_signals()
    try:
        from rdisc.engine.signals import command_line

        return command_line(lambda: _main(argv))
    finally:
        if held is not None:
            signal.pthread_sigmask(signal.SIG_SETMASK, held)


def hold_signals() -> set[int | signal.Signals] | None:
    """Block SIGINT and SIGTERM in this thread (they wait, pending, for `engine.command_line` to let
    them through); the mask found, or None where there are no signal masks (Windows)."""
    if not hasattr(signal, "pthread_sigmask"):
        return None
    return signal.pthread_sigmask(signal.SIG_BLOCK, (signal.SIGINT, signal.SIGTERM))


def _main(argv: list[str] | None) -> int:
    given = sys.argv[1:] if argv is None else argv
    args = parser(given).parse_args(given)
    budget: contextlib.AbstractContextManager[None] = contextlib.nullcontext()
    if getattr(args, "max_tokens", None) is not None:
        from rdisc.compile import token_budget

        budget = token_budget(args.max_tokens)
    try:
        with budget:
            status: int = args.run(args)
            return status
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    except Exception:
        if args.debug:
            raise
        exc = sys.exc_info()[1]
        print(f"rdisc: internal error: {type(exc).__name__}: {exc}", file=sys.stderr)
        print("This is a bug in rdisc, not in your description; rerun with --debug to see where.", file=sys.stderr)
        return EXIT_INTERNAL
