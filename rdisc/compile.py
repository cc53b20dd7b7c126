"""The pipeline, stage by stage: read → parse → resolve → check (→ Model) → budget.

This is the one place that knows the order of the stages; the CLI, the tests and
later the runtime call `compile_path`. A .json file enters through the JSON
importer instead of the parser and goes through the same checker.
"""

from __future__ import annotations

import gc
import os
import stat
from collections.abc import Callable, Iterator, Mapping
from contextlib import contextmanager
from contextvars import ContextVar

from rdisc.diagnostics import Diagnostics, abbreviate
from rdisc.semantics.budget import ConnectionBudget, budget
from rdisc.semantics.check import check
from rdisc.semantics.check.memo import Memo
from rdisc.semantics.model import Model, Value
from rdisc.semantics.resolve import Unit, resolve
from rdisc.source import Sources, Span
from rdisc.syntax import ast
from rdisc.syntax.parse import MAX_FILE_CHARS, parse, token_count

Parser = Callable[[str, str, Diagnostics], ast.Module]  # `parse`, or one as good
MAX_IMPORTS = 256
MAX_TOKENS = 200_000  # of a description and its imports: about seventy times the largest example's
# The budget of descriptions compiled in this context: the command line's --max-tokens (token_budget).
_max_tokens: ContextVar[int] = ContextVar("max_tokens", default=MAX_TOKENS)
# Texts read instead of the files at these real paths: an editor's unsaved documents (open_texts).
_open_texts: ContextVar[Mapping[str, str] | None] = ContextVar("open_texts", default=None)


@contextmanager
def token_budget(tokens: int) -> Iterator[None]:
    """Descriptions compiled inside may have up to `tokens` tokens with their imports: what
    `--max-tokens` gives every verb that reads one, for large descriptions a user trusts."""
    reset = _max_tokens.set(tokens)
    try:
        yield
    finally:
        _max_tokens.reset(reset)


@contextmanager
def open_texts(texts: Mapping[str, str]) -> Iterator[None]:
    """Imports of descriptions compiled inside read `texts[real path]` instead of the file, when
    given: what the language server has in its editor's buffers, saved or not."""
    reset = _open_texts.set(texts)
    try:
        yield
    finally:
        _open_texts.reset(reset)


class Compilation:
    """What checking a description gave (a plain class: `rdisc check` need not import `dataclasses`)."""

    __slots__ = ("budgets", "diagnostics", "main", "model", "sources", "units")

    def __init__(self, model: Model | None, diagnostics: Diagnostics, sources: Sources,
                 budgets: list[ConnectionBudget] | None = None, main: ast.Module | None = None,
                 units: list[Unit] | None = None) -> None:
        self.model = model
        self.diagnostics = diagnostics
        self.sources = sources
        self.budgets = [] if budgets is None else budgets
        self.main = main  # the main file's syntax tree (for `rdisc import`)
        self.units = [] if units is None else units  # every file's syntax tree, the stdlib's too (the editor's index)


def read_text(path: str, diagnostics: Diagnostics, at: Span | None = None) -> str | None:
    """The text of a file, or None with an E006 diagnostic."""
    where = at or Span(path, 0, 0)
    try:  # opened without blocking, and read only if it is a regular file (not a FIFO or a device)
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
        with os.fdopen(fd, "rb") as f:
            if not stat.S_ISREG(os.fstat(f.fileno()).st_mode):
                diagnostics.report("E006", where, f"cannot read {path}: not a regular file")
                return None
            data = f.read(MAX_FILE_CHARS * 4 + 1)
    except (OSError, ValueError) as err:  # ValueError: a NUL in the name
        diagnostics.report("E006", where, f"cannot read {path}: {getattr(err, 'strerror', None) or err}")
        return None
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as err:
        line = data.count(b"\n", 0, err.start) + 1
        diagnostics.report("E006", where, f"{path} is not UTF-8 text (byte {err.start}, line {line})")
        return None


class _Tokens:
    """The tokens a description and its imports may still have. Parsing costs time in
    proportion to them (about 10 us each in Lark), so a file past them is refused before.

    A token is a character or more, so a file of no more characters than the tokens left is within
    them: it is parsed at once, and its tokens are counted only when a file after it is read (they
    are what that one may still have). A description that imports nothing is never counted, which
    was a few percent of checking a small one."""

    def __init__(self, most: int | None = None, parser: Parser | None = None) -> None:
        self.most = _max_tokens.get() if most is None else most
        self.left = self.most
        self.parser = parse if parser is None else parser
        # A parser that counts tokens as `token_count` does, faster (the editor's Reparser).
        self.count: Callable[[str, int], int] = getattr(parser, "tokens", token_count)
        self.uncounted: list[str] = []  # texts parsed, within the tokens left, not yet counted

    def parse(self, path: str, text: str, diagnostics: Diagnostics) -> ast.Module:
        for parsed in self.uncounted:  # in order: each has no more tokens than were left when it was parsed
            self.left -= self.count(parsed, self.left)
        self.uncounted.clear()
        if len(text) <= self.left:
            self.uncounted.append(text)
            return self.parser(path, text, diagnostics)
        count = self.count(text, self.left)
        if count > self.left:
            diagnostics.report("E005", Span(path, 0, 0), f"the description has more than {self.most} tokens, "
                               "with its imports; this file is not read",
                               help="a larger description you trust is read with `--max-tokens N`")
            self.left = 0
            return ast.Module(path, (), refused=True)
        self.left -= count
        return self.parser(path, text, diagnostics)


# Checks since the last full collection of ours, and how many make the next (`_without_collections`).
_CHECKS = [0]
CHECKS_PER_COLLECTION = 32


@contextmanager
def _without_collections() -> Iterator[None]:
    """The cyclic garbage collector paused: a large description is a few million new objects
    and almost no cycles, and the collector's passes over them cost a third of a check, more
    the larger it is (about 10 MB more memory for 40,000 lines). What the check made and kept
    (syntax trees, the Model, the editor's kept checks) lives long: it is put straight in the
    oldest generation (frozen and thawed, each a splice of lists), where the collector's passes
    are rare, not passed over at once by the first young collection after it (a third of an
    editor's check again, when most declarations moved).

    Freezing also resets the collector's counts, so in a process that checks again and again
    (the editor, the console, a fuzzer's worker) its full collection never came, and every cycle
    the process left, the check's or not, stayed for ever. A check leaves none
    (tests/semantics/test_repeated_checks.py); the process's own are collected here, a full
    collection every CHECKS_PER_COLLECTION checks."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        if enabled:
            gc.freeze()
            gc.unfreeze()
            _CHECKS[0] += 1
            if _CHECKS[0] >= CHECKS_PER_COLLECTION:
                _CHECKS[0] = 0
                gc.collect()
            gc.enable()


def compile_path(path: str, max_tokens: int | None = None,
                 settings: Mapping[str, Value] | None = None) -> Compilation:
    """Check one description (.rdis or .json) and build its Model. `max_tokens`: the token
    budget of the description with its imports (default: the context's, MAX_TOKENS).
    `settings`: values given when connecting (each already of its setting's type and range,
    `engine.bind_settings`), which stand for the defaults: the body is built and checked with them."""
    diagnostics = Diagnostics()
    text = read_text(path, diagnostics)
    if text is None:
        return Compilation(None, diagnostics, Sources())
    return compile_text(path, text, diagnostics, max_tokens, settings=settings)


@_without_collections()
def compile_text(path: str, text: str, diagnostics: Diagnostics | None = None,
                 max_tokens: int | None = None, parser: Parser | None = None, memo: Memo | None = None,
                 settings: Mapping[str, Value] | None = None) -> Compilation:
    """Check a description given as text, named `path` (.json for the JSON importer): a ROS
    node rebuilds its Model for `~sim` from the canonical JSON it embeds, with no file. The
    editor's `parser` (of every file read) reuses what did not change since its last check
    (rdisc.syntax.incremental)."""
    diagnostics = diagnostics if diagnostics is not None else Diagnostics()
    sources = Sources()
    sources.add(path, text)
    if memo is not None:  # how each file the parser reads moved since its last parse, for the checks kept
        memo.moved = getattr(parser, "moved", {})
    tokens = _Tokens(max_tokens, parser)
    if path.endswith(".json"):
        from rdisc.json_import.document import read

        main = read(path, text, diagnostics)
    else:
        main = tokens.parse(path, text, diagnostics)
    if main is None:
        return Compilation(None, diagnostics, sources)
    units: list[Unit] = []
    _add_unit(main, True, diagnostics, sources, units, tokens)
    return _analyse(units, diagnostics, sources, main, memo, settings)


@_without_collections()
def compile_module(main: ast.Module, diagnostics: Diagnostics, sources: Sources,
                   max_tokens: int | None = None) -> Compilation:
    """Check an already-built syntax tree (from the JSON importer) with its imports."""
    units: list[Unit] = []
    _add_unit(main, True, diagnostics, sources, units, _Tokens(max_tokens))
    return _analyse(units, diagnostics, sources, main)


def _analyse(units: list[Unit], diagnostics: Diagnostics, sources: Sources, main: ast.Module,
             memo: Memo | None = None, settings: Mapping[str, Value] | None = None) -> Compilation:
    symbols = resolve(units, diagnostics)
    model = check(units, symbols, diagnostics, memo, settings)
    budgets = budget(model, diagnostics) if model is not None else []
    return Compilation(model, diagnostics, sources, budgets, main, units)


def _add_unit(main: ast.Module, is_main: bool, diagnostics: Diagnostics, sources: Sources, units: list[Unit],
              tokens: _Tokens) -> None:
    """Add the stdlib, the main module and every file it imports (transitively, once each).

    The stdlib comes first, so a user's adapter that repeats a standard name is the
    one reported as the duplicate.
    """
    from rdisc.resources import stdlib_file

    stdlib = stdlib_file()
    is_stdlib = os.path.realpath(main.path) == os.path.realpath(stdlib)
    text = None if is_stdlib else read_text(stdlib, diagnostics)
    if text is not None:
        sources.add(stdlib, text)
        units.append(Unit(tokens.parser(stdlib, text, diagnostics), standard=True))
    root = os.path.dirname(os.path.realpath(main.path))
    seen = {os.path.realpath(main.path), os.path.realpath(stdlib)}
    units.append(Unit(main, main=is_main))
    queue = [main]
    while queue:
        module = queue.pop(0)
        for decl in module.decls:
            if not isinstance(decl, ast.ImportDecl):
                continue
            from pathlib import Path  # only for a description that imports: start-up time

            target = Path(module.path).parent / decl.path
            try:
                resolved = target.resolve()
                resolved.stat()  # a name too long, or with a NUL, fails here as it would on reading
            except FileNotFoundError:
                pass  # reported when it is read, as before
            except (OSError, RuntimeError, ValueError) as err:  # RuntimeError: a loop of symbolic links
                diagnostics.report("E007", decl.span, f"cannot import `{abbreviate(decl.path)}`: "
                                   f"{getattr(err, 'strerror', None) or err}")
                continue
            if Path(decl.path).is_absolute() or not decl.path.endswith(".rdis") or not resolved.is_relative_to(Path(root)):
                # A description may come from a device or a network: it reads no other files.
                diagnostics.report("E007", decl.span, f"cannot import `{decl.path}`",
                                   label="not a relative path to an .rdis file in the description's folder")
                continue
            key = str(resolved)
            if key in seen:
                continue
            seen.add(key)
            if len(seen) > MAX_IMPORTS:
                diagnostics.report("E005", decl.span, f"more than {MAX_IMPORTS} imported files")
                return
            if not target.is_file():
                diagnostics.report("E007", decl.span, f"imported file `{decl.path}` does not exist",
                                   label=f"looked for {target}")
                continue
            text = (_open_texts.get() or {}).get(key)
            if text is None:
                text = read_text(str(target), diagnostics, decl.span)
            if text is None:
                continue
            sources.add(str(target), text)
            imported = tokens.parse(str(target), text, diagnostics)
            units.append(Unit(imported))
            queue.append(imported)
