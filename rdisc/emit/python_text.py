"""The small shapes of text the driver writer prints: docstrings, sections, values broken over lines."""

from __future__ import annotations

from collections.abc import Mapping

from rdisc.emit.python_expr import Chain, Paren, Py, lines
from rdisc.emit.writer import Writer, printable
from rdisc.semantics import model as m
from rdisc.semantics.model import Type
from rdisc.syntax import precedence as p

_PY_TYPES = {Type.INT: "int", Type.FLOAT: "float", Type.BOOL: "bool", Type.STRING: "str", Type.BYTES: "bytes"}


def _sample(type_: m.AnyType, comma: str) -> str:
    """A value of `type_` as an example shows it (an array's elements joined by `comma`)."""
    if isinstance(type_, m.Array):
        return "[" + comma.join([_sample(type_.element, comma)] * max(type_.size, 1)) + "]"
    return {Type.INT: "0", Type.FLOAT: "0.0", Type.BOOL: "False", Type.STRING: '""', Type.BYTES: '""'}[type_]


def _py_type(type_: m.AnyType) -> str:
    """The annotation of a value of `type_`: an array is a tuple (a list is taken too)."""
    if isinstance(type_, m.Array):
        return f"Sequence[{_PY_TYPES[type_.element]}]"
    return _PY_TYPES[type_]


def _docstring(text: str) -> str:
    """A triple-quoted docstring that reads back as `text` (its lines right-stripped)."""
    body = "\n".join(line.rstrip() for line in text.strip("\n").split("\n"))
    escaped = printable(body.replace("\\", "\\\\"), keep="\n").replace('"""', '\\"\\"\\"')
    if escaped.endswith('"') and (len(escaped) - 1 - len(escaped[:-1].rstrip("\\"))) % 2 == 0:
        escaped = escaped[:-1] + '\\"'
    if "\n" in escaped:
        return f'"""{escaped}\n"""'
    return f'"""{escaped}"""'


def _construct(w: Writer, prefix: str, name: str, args: list[str], options: Mapping[str, str] = {}) -> None:
    """`prefix name(args, option=value, ...)`, one argument a line when it does not fit on one."""
    items = args + [f"{key}={value}" for key, value in options.items()]
    flat = f"{prefix}{name}({', '.join(items)})"
    if len(flat) <= w.width() and "\n" not in flat:
        w.line(flat)
        return
    w.line(f"{prefix}{name}(")
    with w.indented():
        w.lines([f"{item}," for item in items])
    w.line(")")


def _items(w: Writer, prefix: str, opening: str, values: list[Py], closing: str) -> None:
    """`prefix opening v1, v2 closing` on one line if it fits, else a value a line. Without a
    closing, one value and no brackets."""
    if not closing:
        (value,) = values
        _emit(w, prefix, value)
        return
    flat = f"{prefix}{opening}{', '.join(v.text for v in values)}{closing}"
    if len(flat) <= w.width() and "\n" not in flat:
        w.line(flat)
        return
    w.line(prefix + opening)
    with w.indented():
        for value in values:
            _emit(w, "", value, ",")
    w.line(closing)


def _emit(w: Writer, prefix: str, value: Py, suffix: str = "") -> None:
    """`prefix value suffix` at the writer's depth, the value broken over lines if it is long
    (an operator chain inside parentheses, so that the break is inside them)."""
    width = w.width() - len(prefix) - len(suffix)
    if isinstance(value.shape, Chain) and len(value.text) > width:
        value = Py(f"({value.text})", p.ATOM, Paren(value))
    out = lines(value, width)
    out[0] = prefix + out[0]
    out[-1] += suffix
    w.lines(out)


def _section(w: Writer, title: str) -> None:
    """`# ---- title ----...` to column 100: the parts of the module, as a reader scans them."""
    w.comment(f"---- {title} ".ljust(w.width() - 2, "-"))


def _a(noun: str) -> str:
    return f"{'an' if noun[:1].lower() in 'aeiou' else 'a'} {noun}"


def _wrapped(items: list[str], width: int) -> list[str]:
    """`items` joined by spaces into lines of at most `width` characters (one item a line where it is longer)."""
    out: list[str] = []
    for item in items:
        if out and len(out[-1]) + 1 + len(item) <= width:
            out[-1] += " " + item
        else:
            out.append(item)
    return out


def _tuple(items: list[str]) -> str:
    if not items:
        return "()"
    return f"({items[0]},)" if len(items) == 1 else f"({', '.join(items)})"
