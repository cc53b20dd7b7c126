"""Hover: what a name is. A primitive or frame shows its wire layout, offset and size of every byte
(the table `rdisc dump` prints), a parameter its type, range and unit, an adapter its fields, and
every declaration its `///` doc comment.

The layout needs a Model, which only a check without errors builds: while the document has
errors, the last good check's layout is shown, and said to be.
"""

from __future__ import annotations

from lsprotocol import types

from rdisc.editor import positions
from rdisc.editor.documents import Analysis
from rdisc.editor.index import Symbol
from rdisc.syntax import ast
from rdisc.syntax.printer import print_expr, print_field, print_params, print_type


def hover(analysis: Analysis, good: Analysis | None, at: types.Position) -> types.Hover | None:
    source = analysis.source
    found = analysis.index.at(source.path, positions.offset(source, at))
    if found is None:
        return None
    text = describe(found.symbol, analysis, good)
    return types.Hover(contents=types.MarkupContent(kind=types.MarkupKind.Markdown, value=text),
                       range=positions.to_range(source, found.span))


def describe(symbol: Symbol, analysis: Analysis, good: Analysis | None) -> str:
    """Markdown: the declaration as written, its doc comment, and its layout or fields."""
    node = symbol.declaration
    parts = [f"```rdis\n{_signature(symbol)}\n```"]
    where = _owner(symbol)
    if where:
        parts.append(where)
    doc = getattr(node, "doc", None)
    if doc:
        parts.append(doc)
    if isinstance(node, ast.AdapterDecl) and node.fields:
        parts.append("fields:\n\n" + "\n".join(f"- `{print_field(f)}`" + (f": {f.doc}" if f.doc else "")
                                            for f in node.fields))
    if isinstance(node, ast.EnumDecl) and node.members:
        parts.append("members: " + ", ".join(f"`{m.name.text} = {print_expr(m.value)}`" for m in node.members))
    if isinstance(node, (ast.PrimitiveDecl, ast.FrameDecl)):
        parts.append(_layout(symbol.name, isinstance(node, ast.FrameDecl), analysis, good))
    return "\n\n".join(parts)


def _signature(symbol: Symbol) -> str:
    node = symbol.declaration
    match node:
        case ast.PrimitiveDecl() | ast.InterfaceDecl():
            return f"{symbol.kind} {symbol.name}({print_params(node.params)})"
        case ast.FrameDecl():
            return f"frame {symbol.name}" + (f"({print_params(node.params)})" if node.params else "")
        case ast.Param():
            return print_params((node,))
        case ast.FieldDecl():
            return print_field(node)
        case ast.StateDecl():
            return f"state {symbol.name}: {print_type(node.type)}" + (
                f" = {print_expr(node.init)}" if node.init is not None else "")
        case ast.SensorDecl():
            return f"sensor {symbol.name}: {print_type(node.type)} from {node.primitive.text}() cache " + (
                f"{print_expr(node.cache.value)} {node.cache.unit}")
        case ast.SettingDecl():
            bounds = f" in {print_expr(node.low)}..{print_expr(node.high)}" if node.low and node.high else ""
            return f"setting {symbol.name}: {print_type(node.type)}{bounds}" + (
                f" = {print_expr(node.default)}" if node.default is not None else "")
        case ast.ConstDecl():
            value = node.value
            shown = f"{{ {len(value.entries)} entries }}" if isinstance(value, ast.TableLit) else print_expr(value)
            return f"const {symbol.name} = {shown}"
        case ast.EnumMember():
            return f"{symbol.owner.name if symbol.owner else ''}.{symbol.name} = {print_expr(node.value)}"
        case ast.InputDecl() | ast.OutputDecl():
            return f"{symbol.kind} {symbol.name}: {node.adapter.text}"
    return f"{symbol.kind} {symbol.name}"


def _owner(symbol: Symbol) -> str | None:
    if symbol.owner is None:
        return "declared in the standard library (stdlib/adapters.rdis)" if symbol.standard else None
    return f"{symbol.kind} of {symbol.owner.kind} `{symbol.owner.name}`"


def _layout(name: str, frame: bool, analysis: Analysis, good: Analysis | None) -> str:
    from rdisc.emit.dump import frame_layout, primitive_layout

    note = ""
    model = analysis.compilation.model
    if model is None and good is not None:
        model, note = good.compilation.model, " (from the last check without errors)"
    if model is None:
        return "*the wire layout is shown once the description checks without errors*"
    if frame and name in model.frames:
        table = frame_layout(model.frames[name])
    elif not frame and name in model.primitives:
        table = primitive_layout(model, name)
    else:
        return f"*the wire layout is shown once the description checks without errors{note}*"
    return f"wire layout{note}:\n\n```\n{table.rstrip()}\n```"

