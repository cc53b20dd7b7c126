"""Showing a compilation's diagnostics and writing results: shared by the verbs."""

from __future__ import annotations

import argparse
import sys
from collections.abc import Callable, Iterable

from rdisc.compile import Compilation, compile_path
from rdisc.semantics.model import Model
from rdisc.source import Sources

EXIT_OK, EXIT_ERRORS, EXIT_USAGE = 0, 1, 2


def show(compilations: list[Compilation]) -> None:
    """Diagnostics for people, on stderr; rich is imported only when there are some."""
    items = [d for c in compilations for d in c.diagnostics.sorted()]
    if not items:
        return
    from rich.console import Console

    from rdisc.diagnostics.text import render

    sources = Sources((path, src) for c in compilations for path, src in c.sources.items())
    Console(stderr=True, highlight=False).print(render(items, sources), soft_wrap=True)


def exit_code(compilations: list[Compilation]) -> int:
    if any(d.code == "E006" for c in compilations for d in c.diagnostics.items):
        return EXIT_USAGE
    return EXIT_ERRORS if any(c.diagnostics.has_errors() for c in compilations) else EXIT_OK


def write(text: str, path: str | None, inputs: Iterable[str] = ()) -> int:
    """Write a result to a file, or to stdout when no path is given; never over one of the
    files it was made from (`inputs`: the description and what it imports)."""
    if path is None or path == "-":
        sys.stdout.write(text)
        return EXIT_OK
    from rdisc.engine.command import made_from  # the engine's command line: not for `rdisc check`

    source = made_from(path, inputs)
    if source is not None:
        print(f"rdisc: will not write {path}: it is {source}, which this was made from", file=sys.stderr)
        return EXIT_USAGE
    try:
        with open(path, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
    except OSError as err:
        print(f"rdisc: cannot write {path}: {err.strerror or err}", file=sys.stderr)
        return EXIT_USAGE
    return EXIT_OK


def checked_model(path: str) -> Model | int:
    """The model of a description that checks without errors, its warnings shown; else the
    exit status once its diagnostics are: the start of every verb that runs a description."""
    compilation = checked(path)
    if isinstance(compilation, int):
        return compilation
    assert compilation.model is not None
    return compilation.model


def checked(path: str, given: list[str] | None = None, prog: str = "rdisc") -> Compilation | int:
    """`checked_model`'s compilation, for a verb that needs the files read too (`list(.sources)`),
    its model not None; with `given` settings (`--set NAME=VALUE`), built and checked with them."""
    compilation = with_settings(path, given, prog)
    if isinstance(compilation, int):
        return compilation
    show([compilation])
    if compilation.model is None or compilation.diagnostics.has_errors():
        return exit_code([compilation]) or EXIT_ERRORS
    return compilation


def with_settings(path: str, given: list[str] | None, prog: str) -> Compilation | int:
    """The compilation of a description with the settings `--set NAME=VALUE` gives (`given`), which
    stand for their defaults: its body is built, checked and written with them. Each value is read
    and held to its setting as `rdisc run` does (`engine.bind_settings`); one that does not fit is a
    usage error, said on stderr."""
    compilation = compile_path(path)
    if not given or compilation.model is None or compilation.diagnostics.has_errors():
        return compilation
    from rdisc import engine
    from rdisc.runtime.device import Description

    device = Description(compilation.model).device
    try:
        values = engine.parse_settings(given, device)
        bound = engine.bind_settings(device, values)
    except (TypeError, ValueError) as err:
        print(f"{prog}: {err}", file=sys.stderr)
        return EXIT_USAGE
    return compile_path(path, settings={name: bound[name] for name in values})


def compile_and_write(path: str, output: str | None, render: Callable[[Model, Sources], str],
                      given: list[str] | None = None, prog: str = "rdisc") -> int:
    """Check a description (with the settings `given`), show its diagnostics, and write what
    `render` makes of its model (and the files read) when it has no errors: the shape of every
    verb that turns a description into a file."""
    compilation = with_settings(path, given, prog)
    if isinstance(compilation, int):
        return compilation
    show([compilation])
    if compilation.model is None or compilation.diagnostics.has_errors():
        return exit_code([compilation]) or EXIT_ERRORS
    return write(render(compilation.model, compilation.sources), output, list(compilation.sources))


def add_settings_argument(parser: argparse.ArgumentParser) -> None:
    """`--set NAME=VALUE`, repeated, of the verbs that write the body: as `rdisc run`'s."""
    parser.add_argument("--set", action="append", default=[], metavar="NAME=VALUE",
                        help="give a setting of the description its value (a wheel base the body reads); repeat "
                             "for several; the others keep their defaults")


def emit_body(verb: str, path: str, output: str | None, render: Callable[[Model, Sources], str],
              given: list[str] | None = None) -> int:
    """`compile_and_write` for the body's formats, with the settings `given` (`--set`): a description
    with no body (or one the format cannot hold) is an error of its own, said in a line, exit 1,
    nothing written."""
    from rdisc.emit.body_xml import BodyError
    from rdisc.semantics.meshes import rebased

    files = verb == "emit-mjcf"  # MuJoCo knows no packages: it is given their files

    def render_rebased(model: Model, sources: Sources) -> str:
        return render(rebased(model, output, files=files), sources)  # its meshes' paths from where it is written

    try:
        return compile_and_write(path, output, render_rebased, given, f"rdisc {verb}")
    except BodyError as err:
        print(f"rdisc {verb}: {path}: {err}", file=sys.stderr)
        return EXIT_ERRORS
