"""The Builder's methods for a frame's rules: its sides, parts, fields, escapes and checksum
(rdisc.syntax.build.Rules)."""

from __future__ import annotations

from rdisc import TYPE_CHECKING
from rdisc.syntax import ast
from rdisc.syntax.builder import Guarded, int_value

if TYPE_CHECKING:
    from collections.abc import Callable
    from typing import Any

    from lark.tree import Meta

    from rdisc.syntax.builder import Builder


class FrameRules:
    """A frame's nodes, made of its children."""

    b: Builder

    def frame_decl(self, meta: Meta, c: list[Any]) -> ast.FrameDecl:
        return ast.FrameDecl(self.b.ident(c[0]), c[1] or (), tuple(c[2:]), self.b.span(meta), self.b.doc(meta))

    def f_stuff(self, meta: Meta, c: list[Any]) -> ast.FrameStuff:
        return ast.FrameStuff(self.b.string(c[0]), self.b.string(c[1]), self.b.span(meta))

    def f_escape_xor(self, meta: Meta, c: list[Any]) -> ast.FrameEscape:
        mask = int_value(str(c[1]))
        return ast.FrameEscape(self.b.string(c[0]), (), -1 if mask is None else mask, self.b.string(c[2]),
                               self.b.span(meta))

    def f_escape_table(self, meta: Meta, c: list[Any]) -> ast.FrameEscape:
        return ast.FrameEscape(self.b.string(c[0]), tuple(e for e in c[1:] if e is not None), span=self.b.span(meta))

    def escape_entry(self, meta: Meta, c: list[Any]) -> tuple[ast.StrLit, ast.StrLit]:
        return self.b.string(c[0]), self.b.string(c[1])

    def request_side(self, meta: Meta, c: list[Any]) -> ast.FrameSide:
        return ast.FrameSide("request", tuple(c), self.b.span(meta))

    def reply_side(self, meta: Meta, c: list[Any]) -> ast.FrameSide:
        return ast.FrameSide("reply", tuple(c), self.b.span(meta))

    @staticmethod
    def _bytes(role: str) -> Callable[[Any, Meta, list[Any]], ast.FrameBytes]:
        def part(self: Any, meta: Meta, c: list[Any]) -> ast.FrameBytes:
            return ast.FrameBytes(role, self.b.string(c[0]), self.b.span(meta))
        return part

    f_header, f_literal, f_terminator = _bytes("header"), _bytes("literal"), _bytes("terminator")

    def f_field(self, meta: Meta, c: list[Any]) -> ast.FrameField:
        return ast.FrameField(self.b.ident(c[0]), self.b.string(c[1]), c[2], self.b.span(meta))

    def f_length(self, meta: Meta, c: list[Any]) -> ast.FrameLength:
        fmt, sign, amount = c
        adjust = 0
        if amount is not None:
            adjust = int_value(str(amount)) or 0
            adjust = -adjust if str(sign) == "-" else adjust
        return ast.FrameLength(self.b.string(fmt), adjust, self.b.span(meta))

    def f_bits(self, meta: Meta, c: list[Any]) -> ast.FrameBits:
        return ast.FrameBits(self.b.string(c[0]), tuple(c[1:]), self.b.span(meta))

    def b_length(self, meta: Meta, c: list[Any]) -> ast.FrameBitField:
        width, sign, amount = c
        adjust = int_value(str(amount)) or 0 if amount is not None else 0
        return ast.FrameBitField(None, int_value(str(width)) or 0, None, -adjust if str(sign) == "-" else adjust,
                                 self.b.span(meta))

    def b_field(self, meta: Meta, c: list[Any]) -> ast.FrameBitField:
        return ast.FrameBitField(self.b.ident(c[0]), int_value(str(c[1])) or 0, c[2], 0, self.b.span(meta))

    def f_optional(self, meta: Meta, c: list[ast.FramePart]) -> ast.FrameOptional:
        return ast.FrameOptional(tuple(c), self.b.span(meta))

    def part_run(self, meta: Meta, c: list[ast.FramePart]) -> tuple[ast.FramePart, ...]:
        return tuple(c)

    def when_run(self, meta: Meta, c: list[Any]) -> Guarded:
        condition, *parts = c
        return Guarded(condition, tuple(parts))

    def f_either(self, meta: Meta, c: list[object]) -> ast.FrameEither:
        runs = [run for run in c if isinstance(run, (tuple, Guarded))]
        conditions = tuple(run.condition if isinstance(run, Guarded) else None for run in runs)
        return ast.FrameEither(tuple(run.parts if isinstance(run, Guarded) else run for run in runs),
                               self.b.span(meta), conditions if any(c is not None for c in conditions) else ())

    def f_payload(self, meta: Meta, c: list[Any]) -> ast.FramePayload:
        return ast.FramePayload(self.b.span(meta))

    def f_payload_trimmed(self, meta: Meta, c: list[Any]) -> ast.FramePayload:
        return ast.FramePayload(self.b.span(meta), trimmed=True)

    def f_checksum(self, meta: Meta, c: list[Any]) -> ast.FrameChecksum:
        algorithm, encoding, *options = c
        fmt = None if encoding == "hex" else self.b.string(encoding)
        return ast.FrameChecksum(self.b.string(algorithm), fmt, tuple(options), self.b.span(meta))

    def c_inverted(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        return ast.ChecksumOption("inverted", span=self.b.span(meta))

    def c_reflect(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        side = c[0] if c and c[0] is not None else None
        return ast.ChecksumOption("reflect" if side is None else f"reflect {side}", span=self.b.span(meta))

    def reflect_side(self, meta: Meta, c: list[Any]) -> str:
        return str(c[0])

    def c_setting(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        return ast.ChecksumOption(str(c[0]), c[1], span=self.b.span(meta))

    def c_over(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        names = tuple(self.b.ident(t) for t in c if t is not None)
        return ast.ChecksumOption("over", over=names, span=self.b.span(meta))

    def c_seed(self, meta: Meta, c: list[Any]) -> ast.ChecksumOption:
        return ast.ChecksumOption("seed", over=(self.b.ident(c[0]), self.b.ident(c[1])), span=self.b.span(meta))
