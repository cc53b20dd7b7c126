"""`rdisc adapters [NAME...]`: the domain adapters (thesis §4.11, §7.2.5) with their fields, units
and what each is in every framework rdisc speaks: the ROS 1 message, the ROS 2 message, and the
schema a Foxglove session or an MCAP recording names (ROS 2's, `ros2msg`, its messages CDR).

The standard adapters come from stdlib/adapters.rdis; `--description FILE` adds those a
description declares. The columns are the Model's `Adapter.frameworks`, every emitter's one source:
each adapter's `ros` annotations as each column of stdlib/frameworks.txt makes them, or a row of
that table where a framework names a standard adapter otherwise (rdisc.semantics.frameworks)."""

from __future__ import annotations

import argparse
import json
import sys
from typing import Any

from rdisc.cli.output import EXIT_ERRORS, EXIT_OK, EXIT_USAGE
from rdisc.semantics import model as m

_EMPTY = 'robot adapters { author "rdisc" }\n'  # a description of nothing: only the standard adapters


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("adapters", help="list the domain adapters: fields, units, ROS 1, ROS 2 and Foxglove types")
    p.add_argument("names", nargs="*", metavar="NAME", help="only these adapters (default: all)")
    p.add_argument("--description", metavar="FILE", help="also the adapters this description declares")
    p.add_argument("--format", choices=("text", "json"), default="text")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.compile import compile_path, compile_text

    compilation = compile_text("adapters.rdis", _EMPTY) if args.description is None else compile_path(args.description)
    if compilation.model is None or compilation.diagnostics.has_errors():
        print(f"rdisc: {args.description} does not check: `rdisc check {args.description}` says why", file=sys.stderr)
        return EXIT_ERRORS
    adapters = compilation.model.adapters
    unknown = [name for name in args.names if name not in adapters]
    if unknown:
        print(f"rdisc: no adapter {', '.join(f'`{n}`' for n in unknown)}; `rdisc adapters` lists them",
              file=sys.stderr)
        return EXIT_USAGE
    chosen = [adapters[name] for name in args.names] if args.names else list(adapters.values())
    if args.format == "json":
        print(json.dumps([_json(a) for a in chosen], indent=2, ensure_ascii=False))
    else:
        print("\n\n".join(_text(a) for a in chosen))
    return EXIT_OK


def frameworks(adapter: m.Adapter) -> dict[str, Any]:
    """What the adapter is in each framework of the table, a column each (None: nothing): its type,
    or where the framework names its encodings (Foxglove's), its schema with them."""
    from rdisc.semantics.frameworks import standard

    columns: dict[str, Any] = {}
    for name, *_ in standard().frameworks:
        mapping = adapter.mapping(name)
        columns[name] = None if mapping is None else mapping.type if mapping.schema_encoding is None else {
            "schema": mapping.type, "schemaEncoding": mapping.schema_encoding,
            "messageEncoding": mapping.message_encoding}
    return columns


def _paths(adapter: m.Adapter, at: int) -> dict[str, str | None]:
    """A field's path in each framework the adapter is in."""
    return {mapping.framework: mapping.paths[at] for mapping in adapter.frameworks}


def _type(type_: m.AnyType) -> str:
    if isinstance(type_, m.Array):
        return f"{type_.element.value}[{type_.size or ''}]"
    return type_.value


def _json(adapter: m.Adapter) -> dict[str, Any]:
    """An adapter; a field's `ros` is its ROS path, and `paths` by framework only where they differ."""
    fields = []
    for at, f in enumerate(adapter.fields):
        paths = _paths(adapter, at)
        fields.append({"name": f.name, "type": _type(f.type), "unit": f.unit, "ros": f.ros, "doc": f.doc,
                       **({"paths": paths} if len(set(paths.values())) > 1 else {})})
    return {"name": adapter.name, "standard": adapter.standard, "doc": adapter.doc, **frameworks(adapter),
            "fields": fields}


def _path(adapter: m.Adapter, at: int) -> str:
    """A field's path: the one every framework gives it, else each framework's after its title."""
    paths = _paths(adapter, at)
    if len(set(paths.values())) <= 1:
        return next(iter(paths.values()), None) or adapter.fields[at].ros or "-"
    return ", ".join(f"{m.title} {paths[m.framework] or '-'}" for m in adapter.frameworks)


def _text(adapter: m.Adapter) -> str:
    head = adapter.name + ("" if adapter.standard else "  (declared by the description)")
    lines = [head]
    if adapter.doc:
        lines.append("  " + adapter.doc.split("\n\n")[0].replace("\n", " "))
    if not adapter.frameworks:
        lines.append("  no framework message")
    else:
        lines.append("  " + "   ".join(
            f"{each.title} {each.type}" + (f" ({each.schema_encoding}, {(each.message_encoding or '-').upper()})"
                                           if each.schema_encoding else "") for each in adapter.frameworks))
    rows = [(f.name, _type(f.type), f.unit or "-", _path(adapter, at)) for at, f in enumerate(adapter.fields)]
    widths = [max(len(row[i]) for row in rows) for i in range(3)] if rows else [0, 0, 0]
    lines += ["  " + "  ".join(cell.ljust(widths[i]) if i < 3 else cell for i, cell in enumerate(row)).rstrip()
              for row in rows]
    return "\n".join(lines)
