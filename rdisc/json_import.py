"""JSON description → AST: the canonical JSON of `rdisc build`, and hand-written
thesis-style JSON such as thesis Appendix B.

Every JSON value keeps its place in the file (Lark, grammar/json.lark), so the
checker's diagnostics about an imported description point at the JSON line, and
an expression written `"<...>"` is parsed by the RDIS grammar with spans on the
characters inside the string. Nothing is evaluated: the thesis ran `eval` on these
strings, rdisc reads them as data.

Thesis conventions: `"<expr>"` is an expression; `""` is the default of the type
expected there (0, 0.0, False, ""); any other string is a string literal; a
post-action is `"state = expr"` with the reply called `__out__`. Missing members
default as in thesis Appendix A. Thesis JSON has no types, so parameter types
are inferred: a primitive parameter passed bare as format argument i has the
type of value i of the template (else int); an interface parameter passed bare
to a primitive parameter has that parameter's type (else float). An input or
output without an adapter gets the standard adapter with exactly its fields (for
an input, in its order: else a copy of it in that order), or an adapter of float
fields made for it.

A member of the wrong kind, a missing name or an unknown member is an E008 error
at the offending value, and the element it belongs to is left out (as the parser
leaves out a declaration with a syntax error). Size, nesting and the number of
values are bounded (E005) before Lark sees the text.
"""

from __future__ import annotations

import dataclasses
import difflib
import json
import math
import re
from collections.abc import Callable
from dataclasses import dataclass, fields, is_dataclass, replace
from functools import lru_cache, partial
from typing import TYPE_CHECKING, Any, TypeVar

from rdisc.diagnostics import Diagnostics, Label, abbreviate
from rdisc.limits import MAX_INT
from rdisc.semantics import formats
from rdisc.semantics.operators import FLOAT_FUNCTIONS
from rdisc.source import Span
from rdisc.syntax import ast
from rdisc.syntax.build import MAX_INT_DIGITS
from rdisc.syntax.parse import MAX_FILE_CHARS, parse, parse_expression
from rdisc.syntax.printer import print_expr

if TYPE_CHECKING:
    from lark import Lark, Token, Tree
    from lark.exceptions import UnexpectedInput

MAX_DEPTH = 100  # nesting of JSON arrays and objects
MAX_VALUES = 200_000  # a description has thousands; parsing costs about 15 µs a value

# ---- JSON values with their places -------------------------------------------------------


@dataclass(frozen=True, slots=True)
class JString:
    value: str
    raw: str  # the token as written, quotes and escapes included
    span: Span


@dataclass(frozen=True, slots=True)
class JNumber:
    value: float  # or int
    span: Span


@dataclass(frozen=True, slots=True)
class JBool:
    value: bool
    span: Span


@dataclass(frozen=True, slots=True)
class JNull:
    span: Span


@dataclass(frozen=True, slots=True)
class JArray:
    items: tuple[JValue, ...]
    span: Span


@dataclass(frozen=True, slots=True)
class JObject:
    members: tuple[tuple[JString, JValue], ...]  # duplicates already reported and dropped
    span: Span


JValue = JString | JNumber | JBool | JNull | JArray | JObject
_Kind = TypeVar("_Kind", JString, JNumber, JBool, JNull, JArray, JObject)
_Built = TypeVar("_Built")
Declared = TypeVar("Declared", ast.ConstDecl, ast.EnumDecl)


def read(path: str, text: str, diagnostics: Diagnostics) -> ast.Module | None:
    """The declarations of a JSON description; None if it is not a JSON object."""
    root = read_json(path, text, diagnostics)
    if root is None:
        return None
    if not isinstance(root, JObject):
        diagnostics.report("E008", root.span, f"a description is a JSON object, found {_kind(root)}")
        return None
    return _Importer(path, diagnostics).module(root)


def read_json(path: str, text: str, diagnostics: Diagnostics) -> JValue | None:
    """Any JSON text, with places; None after an E005/E008 diagnostic."""
    if len(text) > MAX_FILE_CHARS:
        diagnostics.report(
            "E005",
            Span(path, 0, 0),
            f"file is too large ({len(text)} characters; the limit is {MAX_FILE_CHARS})",
        )
        return None
    if not _bounded(path, text, diagnostics):
        return None
    import lark

    try:
        tree = _json_parser().parse(text)
    except lark.exceptions.UnexpectedInput as err:
        _report_json_error(err, path, text, diagnostics)
        return None
    return _Values(path, diagnostics).value(tree)


@lru_cache(maxsize=1)
def _json_parser() -> Lark:  # imported lazily like the RDIS parser
    import lark

    from rdisc.resources import grammar_path

    return lark.Lark.open(
        str(grammar_path().with_name("json.lark")),
        parser="lalr",
        lexer="contextual",
        propagate_positions=True,
        cache=True,
    )


# A string (closed or not: each is scanned once), a bracket or a comma.
_STRUCTURE = re.compile(r'"(?:[^"\\\n]|\\.)*"?|[\[\]{},]')


def _bounded(path: str, text: str, diagnostics: Diagnostics) -> bool:
    """Bound the nesting and the number of values before parsing, so that neither
    building values (recursive) nor parsing (time) can be made to explode."""
    depth = values = 0
    for m in _STRUCTURE.finditer(text):
        c = m.group()
        if c in "[{,":
            values += 1
            if values > MAX_VALUES:
                message = f"JSON has too many values (the limit is {MAX_VALUES})"
                diagnostics.report("E005", Span(path, m.start(), m.end()), message)
                return False
        if c in "[{":
            depth += 1
            if depth > MAX_DEPTH:
                message = f"JSON is nested too deeply (the limit is {MAX_DEPTH} levels)"
                diagnostics.report("E005", Span(path, m.start(), m.end()), message)
                return False
        elif c in "]}":
            depth -= 1
    return True


_TOKEN_WORDS = {
    "STRING": "a string",
    "NUMBER": "a number",
    "TRUE": "`true`",
    "FALSE": "`false`",
    "NULL": "`null`",
    "LBRACE": "`{`",
    "RBRACE": "`}`",
    "LSQB": "`[`",
    "RSQB": "`]`",
    "COMMA": "`,`",
    "COLON": "`:`",
    "$END": "the end of the file",
}
_VALUE_START = {"STRING", "NUMBER", "TRUE", "FALSE", "NULL", "LBRACE", "LSQB"}
_STRING_PREFIX = re.compile(r'"(?:[^"\\\x00-\x1f]|\\["\\/bfnrt]|\\u[0-9a-fA-F]{4})*')


def _report_json_error(err: UnexpectedInput, path: str, text: str, diagnostics: Diagnostics) -> None:
    import lark

    if isinstance(err, lark.exceptions.UnexpectedCharacters):
        begin, end, message = _character_error(text, err.pos_in_stream or 0)
        diagnostics.report("E008", Span(path, begin, end), message)
        return
    if not isinstance(err, lark.exceptions.UnexpectedToken):  # UnexpectedEOF, which only Earley raises
        diagnostics.report("E008", Span(path, len(text), len(text)), "invalid JSON: expected more, found the end "
                           "of the file")
        return
    token = err.token
    expected = set(err.interactive_parser.accepts()) if err.interactive_parser else set(err.expected)
    words = ["a value"] if _VALUE_START <= expected else []
    words += sorted(
        _TOKEN_WORDS[t] for t in expected - (_VALUE_START if words else set()) if t in _TOKEN_WORDS
    )
    wanted = words[0] if len(words) == 1 else ", ".join(words[:-1]) + " or " + words[-1]
    if token.type == "$END":
        found, span = "the end of the file", Span(path, len(text), len(text))
    else:
        shown = str(token) if len(token) <= 30 else str(token)[:27] + "..."
        found, span = f"`{shown}`", Span(path, token.start_pos or 0, token.end_pos or 0)
    trailing = token.type in ("RBRACE", "RSQB") and text[: span.start].rstrip().endswith(",")
    help = "JSON allows no comma after the last member or item" if trailing else None
    diagnostics.report("E008", span, f"invalid JSON: expected {wanted}, found {found}", help=help)


def _character_error(text: str, at: int) -> tuple[int, int, str]:
    """Where and why no token starts at `at`: in a string, the character that ends it."""
    if text[at] != '"':
        shown = text[at] if text[at].isprintable() else repr(text[at])[1:-1]
        return at, at + 1, f"invalid JSON: unexpected character `{shown}`"
    prefix = _STRING_PREFIX.match(text, at)
    bad = prefix.end() if prefix else at
    char = text[bad] if bad < len(text) else ""
    if char == "\\":
        return bad, bad + 2, f"invalid JSON: unknown escape `{text[bad : bad + 2]}` in a string"
    if char in ("", "\n", "\r"):
        return at, bad, "invalid JSON: unterminated string"
    return (
        bad,
        bad + 1,
        f"invalid JSON: control character U+{ord(char):04X} in a string (write it as an escape)",
    )


class _Values:
    """Lark tree → JSON values (recursion bounded by `_bounded`)."""

    def __init__(self, path: str, diagnostics: Diagnostics) -> None:
        self.path = path
        self.d = diagnostics

    def value(self, node: Tree[Token] | Token) -> JValue:
        import lark

        if isinstance(node, lark.Token):
            span = Span(self.path, node.start_pos or 0, node.end_pos or 0)
            if node.type == "STRING":
                text = json.loads(node)
                if any(0xD800 <= ord(ch) <= 0xDFFF for ch in text):  # a lone surrogate escape: no character
                    self.d.report("E008", span, "a string holds half of a surrogate pair (`\\udXXX` alone), "
                                                "which is not a character")
                    text = "".join("\ufffd" if 0xD800 <= ord(ch) <= 0xDFFF else ch for ch in text)
                return JString(text, str(node), span)
            if node.type == "NUMBER":
                return JNumber(self.number(str(node), span), span)
            if node.type == "NULL":
                return JNull(span)
            return JBool(node.type == "TRUE", span)
        span = Span(self.path, node.meta.start_pos, node.meta.end_pos)
        if node.data == "array":
            return JArray(tuple(self.value(c) for c in node.children), span)
        members: dict[str, tuple[JString, JValue]] = {}
        for member in node.children:
            assert isinstance(member, lark.Tree)  # the grammar's `member`: a key and its value
            key, value = self.value(member.children[0]), self.value(member.children[1])
            assert isinstance(key, JString)
            if key.value in members:
                first = members[key.value][0].span
                self.d.report(
                    "E008",
                    key.span,
                    f"duplicate member `{key.value}`",
                    labels=(Label(first, "first given here"),),
                )
                continue
            members[key.value] = (key, value)
        return JObject(tuple(members.values()), span)

    def number(self, token: str, span: Span) -> float:
        integral = not any(c in token for c in ".eE")
        if integral and len(token.lstrip("-")) > MAX_INT_DIGITS:
            self.d.report("E004", span, f"integer with more than {MAX_INT_DIGITS} digits")
            return 0
        value: int | float = json.loads(token)
        if integral and abs(value) > MAX_INT:
            self.d.report("E004", span, f"integer {abbreviate(token)} is too large: integers are limited to 64 bits "
                                        f"and a sign (at most {MAX_INT} either way)")
            return 0
        if not integral and math.isinf(value):
            self.d.report("E004", span, "number too large for a float")
            return 0.0
        return value


_KINDS = {JString: "a string", JNumber: "a number", JBool: "true/false", JNull: "null", JArray: "an array",
          JObject: "an object"}  # fmt: skip


def _kind(v: JValue) -> str:
    return _KINDS[type(v)]


# ---- the description ----------------------------------------------------------------------

_TOP = (
    "name", "author", "description", "version", "doc", "constants", "enums", "tables", "constantDocs", "enumDocs",
    "settings",
    "stateVariables", "connections", "frames", "primitives", "interfaces", "domainAdapters", "domainInterfaces", "domainOutputs",
    "links", "joints", "transmissions",
)  # fmt: skip
_SECTIONS = {  # list member: (its elements in words, the RDIS keyword declaring one)
    "settings": ("a setting", "setting"),
    "stateVariables": ("a state variable", "state"),
    "spp": ("a connection", "connection"),
    "tcp": ("a connection", "connection"),
    "frames": ("a frame", "frame"),
    "primitives": ("a primitive", "primitive"),
    "interfaces": ("an interface", "interface"),
    "domainAdapters": ("an adapter", "adapter"),
    "domainInterfaces": ("a domain interface", "input"),
    "domainOutputs": ("a domain output", "output"),
    "links": ("a link", "link"),
    "joints": ("a joint", "joint"),
    "transmissions": ("a transmission", "transmission"),
}
_STATE = ("name", "type", "value", "doc")
_SETTING = ("name", "type", "range", "value", "doc")
_CONNECTION = (
    "name", "baud", "dataBits", "parity", "stopBits", "singleThreading", "startup", "terminate", "keepalive",
    "terminator", "address", "doc",
)  # fmt: skip
_PRIMITIVE = (
    "name", "parameters", "parameterTypes", "parameterRanges", "parameterDefaults", "parameterUnits", "connection",
    "lines", "pack", "format", "formatArgs", "unpack", "regex", "recordsUntil", "frame", "skipUnmatched",
    "replyTable", "timeout", "retry", "replies", "repliesEach", "replyFrames", "replyList", "error", "expect", "postActions", "doc",
)  # fmt: skip
_FRAME = ("name", "parameters", "parameterTypes", "parameterRanges", "parameterDefaults", "parameterUnits",
          "request", "reply", "moreRequests", "moreReplies", "requestWhen",
          "stuffing", "escaping", "doc")
_CHECKSUM = (
    "checksum", "kind", "width", "poly", "init", "reflectIn", "reflectOut", "xorOut", "inverted", "mask", "format",
    "covers", "withRequest", "seed",
)  # fmt: skip
_BYTES_ROLES = ("header", "literal", "terminator")
_INTERFACE = (
    "name", "type", "parameters", "parameterTypes", "parameterRanges", "parameterDefaults", "parameterUnits",
    "primitiveCalls", "triggers", "doc",
)  # fmt: skip
_CALL = ("name", "arguments", "delay", "priority", "when", "until", "every", "within")
_ADAPTER = ("name", "ros", "fields", "doc")
_FIELD = ("name", "type", "unit", "ros", "doc")
_INPUT = ("name", "adapter", "parameters", "calls", "doc")
_OUTPUT = ("name", "adapter", "frame", "returns", "doc")
_LINK = ("name", "visuals", "collisions", "inertial", "doc")
_SHAPE = ("shape", "path", "size", "scale", "xyz", "rpy")
_INERTIAL = ("mass", "centre", "inertia")
_JOINT = ("name", "type", "parent", "child", "xyz", "rpy", "axis", "limit", "velocity", "effort", "damping",
          "friction", "doc")
_TRANSMISSION = ("name", "joint", "commands", "measures", "doc")
_COMMAND = ("quantity", "primitive", "interface", "parameter", "index", "toDevice", "toJoint")
_MEASURE = ("quantity", "state", "index", "toDevice", "toJoint")

DEFAULT_BAUD = 9600  # thesis Appendix A; written out, so the .rdis says what the robot gets
DEFAULT_FREQUENCY_HZ = 10
_DEFAULTS: dict[str, Any] = {"int": 0, "float": 0.0, "bool": False, "string": "", "bytes": b""}
_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_]*")
_ARRAY_TYPE = re.compile(r"([A-Za-z][A-Za-z0-9_]*)\[([0-9]{0,6})\]")


def _type_text(t: ast.TypeRef) -> str:
    """A declared type's name, as the importer compares it: an array's as `int[]`."""
    return f"{t.element.text}[]" if isinstance(t, ast.ArrayOf) else t.text
_FLOAT_SPECS = frozenset("eEfFgG%")

Members = dict[str, JValue]


@lru_cache(maxsize=1)
def _standard_adapters() -> dict[str, ast.AdapterDecl]:
    """The standard adapters (stdlib/adapters.rdis), by name."""
    from rdisc.resources import stdlib_path

    path = stdlib_path()
    module = parse(str(path), path.read_text(encoding="utf-8"), Diagnostics())
    return {d.name.text: d for d in module.decls if isinstance(d, ast.AdapterDecl)}


class _Importer:
    def __init__(self, path: str, diagnostics: Diagnostics) -> None:
        self.path = path
        self.d = diagnostics
        self.standard = _standard_adapters()
        self.adapter_fields = {name: {f.name.text: _type_text(f.type) for f in a.fields} for name, a in self.standard.items()}
        self.primitive_types: dict[str, tuple[str, ...]] = {}
        self.interface_types: dict[str, tuple[str, ...]] = {}
        self.made_adapters: list[ast.AdapterDecl] = []
        self.frame_types: dict[str, tuple[str, ...]] = {}
        self.damaged: list[ast.Damaged] = []

    # -- the whole document, in an order where every type a default needs is known --

    def module(self, root: JObject) -> ast.Module:
        top = self.members(root, "the description", _TOP)
        robot = self.robot(root, top)
        constants = self.documented(self.constants(top.get("constants")) + self.tables(top.get("tables")),
                                    top.get("constantDocs"), "`constantDocs`",
                                    _keys(top.get("constants")) | _keys(top.get("tables")))
        enums = self.documented(self.enums(top.get("enums")), top.get("enumDocs"), "`enumDocs`",
                                _keys(top.get("enums")))
        frames = self.each(top, "frames", self.frame)
        settings = self.each(top, "settings", self.setting)
        states = self.each(top, "stateVariables", self.state)
        primitives = self.each(top, "primitives", self.primitive)
        interfaces = self.each(top, "interfaces", self.interface)
        connections = self.connections(top.get("connections"))
        adapters = self.each(top, "domainAdapters", self.adapter)
        inputs = self.each(top, "domainInterfaces", self.input)
        outputs = self.each(top, "domainOutputs", self.output)
        links = self.each(top, "links", self.link)
        joints = self.each(top, "joints", self.joint)
        transmissions = self.each(top, "transmissions", self.transmission)
        decls: list[ast.Decl] = [] if robot is None else [robot]
        decls += [
            *constants,
            *enums,
            *settings,
            *states,
            *connections,
            *frames,
            *primitives,
            *interfaces,
            *adapters,
            *self.made_adapters,
            *inputs,
            *outputs,
            *links,
            *joints,
            *transmissions,
        ]
        return ast.Module(self.path, tuple(decls), tuple(self.damaged))

    def each(self, top: Members, key: str, build: Callable[[JObject], Any]) -> list[Any]:
        """The elements of a list member. An element with an error is left out, and
        its name kept as damaged, so that references to it are not reported again."""
        what, keyword = _SECTIONS[key]
        built = []
        for item in self.array(top.get(key), f"`{key}`"):
            obj = self.object(item, what)
            if obj is None:
                continue
            errors = self.d.error_count
            element = build(obj)
            if element is not None and self.d.error_count == errors:
                built.append(element)
                continue
            name = next((v for k, v in obj.members if k.value == "name"), None)
            if isinstance(name, JString) and _NAME.fullmatch(name.value):
                self.damaged.append(ast.Damaged(keyword, ast.Ident(name.value, self.inner(name))))
        return built

    # -- elements --

    def robot(self, root: JObject, top: Members) -> ast.RobotDecl | None:
        name = self.name(root, top, "the description")
        attrs = []
        for key in ("author", "description", "version"):
            s = self.string(top.get(key), f"`{key}`")
            if s is not None:
                attrs.append(ast.RobotAttr(key, s.value, s.span))
        doc = self.doc(top)
        return None if name is None else ast.RobotDecl(name, tuple(attrs), root.span, doc)

    def tables(self, value: JValue | None) -> list[ast.ConstDecl]:
        """`tables`: each a list of `[key, value]` pairs."""
        obj = self.object(value, "`tables`") if value is not None else None
        built = []
        for key, item in obj.members if obj else ():
            name = self.ident(key, "a table")
            entries = []
            for pair in self.array(item, "a table"):
                both = self.array(pair, "a table entry")
                if len(both) != 2:
                    self.error(pair.span, "a table entry is `[key, value]`")
                    continue
                k, v = self.expr(both[0], None), self.expr(both[1], None)
                if k is not None and v is not None:
                    entries.append((k, v))
            if name is not None:
                built.append(ast.ConstDecl(name, ast.TableLit(tuple(entries), item.span), key.span))
        return built

    def constants(self, value: JValue | None) -> list[ast.ConstDecl]:
        obj = self.object(value, "`constants`") if value is not None else None
        built = []
        for key, item in obj.members if obj else ():
            name, expr = self.ident(key, "a constant"), self.expr(item, None)
            if name is not None and expr is not None:
                built.append(ast.ConstDecl(name, expr, key.span))
        return built

    def documented(self, decls: list[Declared], value: JValue | None, what: str, named: set[str]) -> list[Declared]:
        """The constants or enums with their doc comments from `constantDocs` or `enumDocs`
        (name: text), which their plain JSON values have no place for; `named`: the names the
        JSON declares (one in error among them is reported once, as itself)."""
        docs = self.object(value, what) if value is not None else None
        texts = {key.value: text.value for key, item in docs.members
                 if (text := self.string(item, "a doc comment")) is not None} if docs else {}
        for key, _ in docs.members if docs else ():
            if key.value not in named:
                self.error(key.span, f"{what} names `{key.value}`, which the description does not declare")
        return [dataclasses.replace(d, doc=texts[d.name.text]) if d.name.text in texts else d for d in decls]

    def enums(self, value: JValue | None) -> list[ast.EnumDecl]:
        obj = self.object(value, "`enums`") if value is not None else None
        built = []
        for key, item in obj.members if obj else ():
            name, members = self.ident(key, "an enum"), self.object(item, "an enum")
            if name is None or members is None:
                continue
            made = []
            for member, number in members.members:
                ident, expr = self.ident(member, "an enum member"), self.expr(number, "int")
                if ident is not None and expr is not None:
                    made.append(ast.EnumMember(ident, expr, member.span))
            built.append(ast.EnumDecl(name, tuple(made), key.span))
        return built

    def framed(self, v: JValue | None) -> ast.Framed | None:
        """`{"name": ..., "arguments": [...]}`: a primitive's frame, or a listed reply's."""
        framed = self.object(v, "`frame`")
        if framed is None:
            return None
        f = self.members(framed, "`frame`", ("name", "arguments"))
        frame = self.name(framed, f, "`frame`")
        if frame is None:
            return None
        return ast.Framed(frame, self.args(f.get("arguments"), self.frame_types.get(frame.text, ())), framed.span)

    def listed_reply(self, v: JValue) -> ast.ListedReply | None:
        """One reply of `"replyList"`: its frame, `unpack` or `regex`, `expect` and post-actions."""
        obj = self.object(v, "a listed reply")
        if obj is None:
            return None
        r = self.members(obj, "a listed reply", ("frame", "unpack", "regex", "expect", "postActions"))
        kind = next((k for k in ("unpack", "regex") if k in r), None)
        template = self.string(r.get(kind), f"`{kind}`") if kind else None
        if kind is None or template is None:
            if kind is None:
                self.error(obj.span, "a listed reply has `unpack` or `regex`")
            return None
        decoding = ast.Decoding(kind, ast.StrLit(template.value, template.span), template.span)
        expect = self.reply_expr(r["expect"], "`expect`") if "expect" in r else None
        assigns = _present([self.post_action(a) for a in self.array(r.get("postActions"), "`postActions`")])
        actions = ast.Actions(assigns, r["postActions"].span) if assigns else None
        return ast.ListedReply(decoding, obj.span, self.framed(r.get("frame")), expect, actions)

    def error_reply(self, v: JValue) -> ast.ErrorReply | None:
        """`"error"`: the reply the device may send instead: its frame, marker, `unpack` and `codes`."""
        obj = self.object(v, "`error`")
        if obj is None:
            return None
        e = self.members(obj, "`error`", ("frame", "marker", "unpack", "codes", "when"))
        codes = self.ident(e["codes"], "`codes`") if "codes" in e else None
        if "when" in e:  # `error when COND`: the reply itself, decoded as ever
            if "unpack" in e or "frame" in e or "marker" in e:
                self.error(obj.span, "an error reply `when` a condition holds has no `frame`, `marker` or `unpack`")
                return None
            condition = self.reply_expr(e["when"], "`when`")
            return None if condition is None else ast.ErrorReply(None, obj.span, codes=codes, when=condition)
        template = self.string(e.get("unpack"), "`unpack`")
        if template is None:
            if "unpack" not in e:
                self.error(obj.span, "an error reply has `unpack` (or `when`)")
            return None
        marker = self.string(e.get("marker"), "`marker`")
        decoding = ast.Decoding("unpack", ast.StrLit(template.value, template.span), template.span)
        return ast.ErrorReply(decoding, obj.span, self.framed(e.get("frame")),
                              None if marker is None else ast.StrLit(marker.value, marker.span), codes)

    def reply_table(self, obj: JObject) -> ast.ReplyTable:
        t = self.members(obj, "`replyTable`", ("key", "tag", "each", "length", "cases"))
        tag = self.string(t.get("tag"), "`tag`")
        flag = t.get("each")
        each = isinstance(flag, JBool) and flag.value
        if flag is not None and not isinstance(flag, JBool):
            self.error(flag.span, "`each` is true or false")
        length = self.string(t.get("length"), "`length`")
        if tag is not None:
            key = ast.Ident("tag", tag.span)
        else:
            named = self.required(obj, t, "key", "`replyTable`", self.ident)
            key = named or ast.Ident("", obj.span)
        entries = []
        for item in self.array(t.get("cases"), "`cases`"):
            case = self.object(item, "a reply table entry")
            if case is None:
                continue
            c = self.members(case, "a reply table entry", ("value", "last", "unpack", "regex", "until", "postActions",
                                                            "tag", "cases"))
            value = self.required(case, c, "value", "a reply table entry", lambda v, _: self.expr(v, "int"))
            last = self.expr(c["last"], "int") if "last" in c else None  # a range entry: `value..last`
            if "tag" in c and value is not None:  # a nested table: the next tag chooses among its entries
                inner = self.reply_table(JObject(tuple(kv for kv in case.members if kv[0].value in ("tag", "cases")),
                                                 case.span))
                entries.append(ast.ReplyEntry(value, None, None, case.span, last, table=inner))
                continue
            kind = next((k for k in ("unpack", "regex") if k in c), None)
            template = self.string(c.get(kind), f"`{kind}`") if kind else None
            if value is None or kind is None or template is None or ("last" in c and last is None):
                if kind is None:
                    self.error(case.span, "a reply table entry has `unpack` or `regex`")
                continue
            assigns = _present([self.post_action(a) for a in self.array(c.get("postActions"), "`postActions`")])
            decoding = ast.Decoding(kind, ast.StrLit(template.value, template.span), template.span)
            actions = ast.Actions(assigns, c["postActions"].span) if assigns else None
            until = self.string(c["until"], "`until`") if "until" in c else None
            entries.append(ast.ReplyEntry(value, decoding, actions, case.span, last,
                                          None if until is None else ast.StrLit(until.value, until.span)))
        if (each or length is not None) and tag is None:
            self.error(obj.span, "a reply table of sub-payloads (`each`, `length`) has a `tag`")
        return ast.ReplyTable(key, tuple(entries), obj.span,
                              None if tag is None else ast.StrLit(tag.value, tag.span), each and tag is not None,
                              None if length is None or tag is None else ast.StrLit(length.value, length.span))

    def frame(self, obj: JObject) -> ast.FrameDecl | None:
        m = self.members(obj, "a frame", _FRAME)
        name = self.name(obj, m, "a frame")
        params = self.params(m, lambda _: "int")
        sides: dict[str, tuple[ast.FramePart, ...]] = {}
        for side, more in (("request", "moreRequests"), ("reply", "moreReplies")):
            layouts = [self.frame_parts(m.get(side), f"`{side}`"),
                       *(self.frame_parts(v, "a layout") for v in self.array(m.get(more), f"`{more}`"))]
            when: tuple[ast.Expr | None, ...] = ()
            if side == "request" and "requestWhen" in m:  # `either when`: a condition (or null) per layout
                when = tuple(None if isinstance(v, JNull) else self.expr(v, "bool")
                             for v in self.array(m["requestWhen"], "`requestWhen`"))
                if len(when) != len(layouts) or len(layouts) < 2:
                    self.error(m["requestWhen"].span, f"`requestWhen` has {len(when)} condition{'' if len(when) == 1 else 's'} for "
                               f"{len(layouts)} request layout{'' if len(layouts) == 1 else 's'}",
                               help="give a condition (or null, the last only) for `request` and each of `moreRequests`")
                    when = ()
            sides[side] = layouts[0] if len(layouts) == 1 and not when else (
                ast.FrameEither(tuple(layouts), m[more].span if more in m else m[side].span, when),)
        if name is None:
            return None
        self.frame_types[name.text] = tuple(_type_text(p.type) for p in params)
        written = {side: m[side] for side in ("request", "reply") if side in m}
        if sides["request"] == sides["reply"]:  # one sequence for both directions
            items: tuple[ast.FramePart | ast.FrameSide | ast.FrameStuff | ast.FrameEscape, ...] = sides["request"]
        else:
            items = tuple(ast.FrameSide(side, parts, written[side].span if side in written else obj.span)
                          for side, parts in sides.items() if parts or side == "request")
        stuffing = self.object(m.get("stuffing"), "`stuffing`")
        if stuffing is not None:
            s = self.members(stuffing, "`stuffing`", ("after", "insert"))
            after, insert = self.string(s.get("after"), "`after`"), self.string(s.get("insert"), "`insert`")
            if after is not None and insert is not None:
                items += (ast.FrameStuff(ast.StrLit(insert.value, insert.span), ast.StrLit(after.value, after.span),
                                         stuffing.span),)
        escaping = self.object(m.get("escaping"), "`escaping`")
        if escaping is not None:
            e = self.members(escaping, "`escaping`", ("escape", "codes"))
            escape = self.required(escaping, e, "escape", "`escaping`", self.string)
            codes = self.required(escaping, e, "codes", "`escaping`", self.object)
            if escape is not None and codes is not None:
                table = []
                for key, value in codes.members:
                    code = self.string(value, "a code")
                    if code is not None:
                        table.append((ast.StrLit(key.value, key.span), ast.StrLit(code.value, code.span)))
                items += (ast.FrameEscape(ast.StrLit(escape.value, escape.span), tuple(table), span=escaping.span),)
        return ast.FrameDecl(name, params, items, obj.span, self.doc(m))

    def frame_parts(self, value: JValue | None, what: str) -> tuple[ast.FramePart, ...]:
        """One layout's parts; `{"optional": N}` takes the N parts after it into an `optional`."""
        objs = [self.object(p, "a frame part") for p in self.array(value, what)]
        out: list[ast.FramePart | None] = []
        at = 0
        while at < len(objs):
            obj = objs[at]
            at += 1
            if obj is None or not any(k.value == "optional" for k, _ in obj.members):
                out.append(None if obj is None else self.frame_part(obj, objs))
                continue
            count = self.members(obj, "an optional part", ("optional",)).get("optional")
            if not (isinstance(count, JNumber) and count.value == int(count.value) and 1 <= count.value <= len(objs) - at):
                self.error(obj.span, f"`optional` is the number of parts after it that a reply may lack (1 to "
                                     f"{len(objs) - at})")
                continue
            inner = [None if p is None else self.frame_part(p, objs) for p in objs[at : at + int(count.value)]]
            out.append(ast.FrameOptional(_present(inner), obj.span))
            at += int(count.value)
        return _present(out)

    def frame_part(self, obj: JObject, side: list[JObject | None]) -> ast.FramePart | None:
        keys = [k.value for k, _ in obj.members]
        role = next((r for r in _BYTES_ROLES if r in keys), None)
        if role is not None:
            m = self.members(obj, f"a `{role}` part", (role,))
            s = self.string(m.get(role), f"`{role}`")
            return None if s is None else ast.FrameBytes(role, ast.StrLit(s.value, s.span), obj.span)
        if "field" in keys:
            m = self.members(obj, "a frame field", ("field", "format", "value"))
            name, fmt = self.ident(m["field"], "`field`"), self.string(m.get("format"), "`format`")
            value = self.required(obj, m, "value", "a frame field", lambda v, _: self.expr(v, "int"))
            if name is None or fmt is None or value is None:
                return None
            return ast.FrameField(name, ast.StrLit(fmt.value, fmt.span), value, obj.span)
        if "length" in keys:
            m = self.members(obj, "a length part", ("length", "adjust"))
            fmt, adjust = self.string(m.get("length"), "`length`"), m.get("adjust")
            if fmt is None:
                return None
            amount = int(adjust.value) if isinstance(adjust, JNumber) else 0
            return ast.FrameLength(ast.StrLit(fmt.value, fmt.span), amount, obj.span)
        if "bits" in keys:
            return self.bits(obj)
        if "payload" in keys:
            given = self.members(obj, "a payload part", ("payload",)).get("payload")
            trimmed = isinstance(given, JString) and given.value == "trimmed"
            if not trimmed and not isinstance(given, JBool):
                self.error(obj.span, 'a payload part is `"payload": true` or `"payload": "trimmed"`')
            return ast.FramePayload(obj.span, trimmed)
        if "checksum" in keys:
            return self.checksum(obj, side)
        self.error(obj.span, "a frame part is one of header, literal, terminator, field, length, bits, payload, "
                             "checksum, optional")
        return None

    def bits(self, obj: JObject) -> ast.FrameBits | None:
        """`{"bits": "<I", "fields": [{"length": true, "width": 30, "adjust": 0}, {"field": "mode", ...}]}`."""
        m = self.members(obj, "a bits part", ("bits", "fields"))
        fmt = self.string(m.get("bits"), "`bits`")
        out: list[ast.FrameBitField | None] = []
        for entry in self.array(m.get("fields"), "`fields`"):
            o = self.object(entry, "a bit field")
            if o is None:
                out.append(None)
                continue
            keys = [k.value for k, _ in o.members]
            f = self.members(o, "a bit field", ("length", "adjust", "width") if "length" in keys else
                             ("field", "width", "value"))
            width = f.get("width")
            if not (isinstance(width, JNumber) and width.value == int(width.value)):
                self.error(o.span, "a bit field has a `width`: its number of bits")
                out.append(None)
                continue
            if "length" in keys:
                adjust = f.get("adjust")
                out.append(ast.FrameBitField(None, int(width.value), None,
                                             int(adjust.value) if isinstance(adjust, JNumber) else 0, o.span))
                continue
            name = self.required(o, f, "field", "a bit field", self.ident)
            value = self.required(o, f, "value", "a bit field", lambda v, _: self.expr(v, "int"))
            out.append(None if name is None or value is None else
                       ast.FrameBitField(name, int(width.value), value, 0, o.span))
        return None if fmt is None else ast.FrameBits(ast.StrLit(fmt.value, fmt.span), _present(out), obj.span)

    def checksum(self, obj: JObject, side: list[JObject | None]) -> ast.FrameChecksum | None:
        m = self.members(obj, "a checksum", _CHECKSUM)
        name, fmt = self.string(m.get("checksum"), "`checksum`"), self.string(m.get("format"), "`format`")
        if name is None or fmt is None:
            return None
        options: list[ast.ChecksumOption] = []
        given = m.get("inverted")
        if isinstance(given, JBool) and given.value:
            options.append(ast.ChecksumOption("inverted", span=given.span))
        # `reflect` is written only for a CRC given by its parameters: a catalogue CRC fixes its own
        if name.value.lower() in ("crc", "sum", "xor"):
            ways = [isinstance(way, JBool) and way.value for way in (m.get("reflectIn"), m.get("reflectOut"))]
            if any(ways):
                word = "reflect" if all(ways) else ("reflect in" if ways[0] else "reflect out")
                options.append(ast.ChecksumOption(word, span=m["reflectIn" if ways[0] else "reflectOut"].span))
        settings = ("mask", "width", "poly", "init", "xorOut") if name.value.lower() == "crc" else ("mask",)
        for key in settings:
            if isinstance(m.get(key), JNumber):
                options.append(ast.ChecksumOption(key.lower(), self.expr(m[key], "int"), span=m[key].span))
        covers = self.array(m.get("covers"), "`covers`")
        here = side.index(obj)
        numbers = [c.value for c in covers if isinstance(c, JNumber)]
        if len(covers) == 2 and len(numbers) == 2:
            first, last = numbers
            if not (first == int(first) and last == int(last) and 0 <= first <= last < here):
                self.d.report("E008", m["covers"].span, f"`covers` is [first, last], the indexes of two parts before "
                                                        f"the checksum (0 to {here - 1}), first <= last")
                first, last = (1 if here > 1 else 0), here - 1
            first, last = int(first), int(last)
            with_request = m.get("withRequest")
            request = isinstance(with_request, JBool) and with_request.value
            header = side and side[0] is not None and any(k.value == "header" for k, _ in side[0].members)
            if request or (first, last) != (1 if header else 0, here - 1):
                names = [_part_name(p) for p in side]
                over = ([ast.Ident("request", m["covers"].span)] if request else
                        [ast.Ident(names[first], m["covers"].span)])
                over.append(ast.Ident(names[last], m["covers"].span))
                options.append(ast.ChecksumOption("over", over=tuple(over), span=m["covers"].span))
        if "seed" in m:
            seed = self.members(m["seed"], "a checksum's seed", ("table", "field")) \
                if isinstance(m["seed"], JObject) else {}
            table, field = (self.string(seed.get(word), f"the seed's `{word}`") for word in ("table", "field"))
            if table is None or field is None:
                self.d.report("E008", m["seed"].span, 'a checksum\'s `seed` is {"table": NAME, "field": NAME}')
            else:
                options.append(ast.ChecksumOption("seed", over=(ast.Ident(table.value, table.span),
                                                                ast.Ident(field.value, field.span)), span=m["seed"].span))
        encoding = None if fmt.value == "hex" else ast.StrLit(fmt.value, fmt.span)
        return ast.FrameChecksum(ast.StrLit(name.value, name.span), encoding, tuple(options), obj.span)

    def state(self, obj: JObject) -> ast.StateDecl | None:
        m = self.members(obj, "a state variable", _STATE)
        name = self.name(obj, m, "a state variable")
        type_ = self.required(obj, m, "type", "a state variable", self.type_ref)
        init = None if "value" not in m else self.expr(m["value"], _type_text(type_) if type_ else None)
        if name is None or type_ is None:
            return None
        return ast.StateDecl(name, type_, init, obj.span, self.doc(m))

    def setting(self, obj: JObject) -> ast.SettingDecl | None:
        m = self.members(obj, "a setting", _SETTING)
        name = self.name(obj, m, "a setting")
        type_ = self.required(obj, m, "type", "a setting", self.type_ref)
        default = None if "value" not in m else self.expr(m["value"], _type_text(type_) if type_ else None)
        low = high = None
        if "range" in m:
            bounds = self.array(m["range"], "a setting's range")
            if len(bounds) != 2:
                self.error(m["range"].span, "a setting's range is `[low, high]`")
                return None
            low, high = self.expr(bounds[0], None), self.expr(bounds[1], None)
        if name is None or type_ is None:
            return None
        return ast.SettingDecl(name, type_, default, obj.span, self.doc(m), low, high)

    def connections(self, value: JValue | None) -> list[ast.ConnectionDecl]:
        groups = self.object(value, "`connections`") if value is not None else None
        built = []
        for key, group in groups.members if groups else ():
            if key.value not in ("spp", "tcp"):
                self.error(
                    key.span,
                    f"unknown connection kind `{key.value}`",
                    help="serial connections are listed under `spp`, TCP ones under `tcp`",
                )
                continue
            kind = ast.Ident("serial" if key.value == "spp" else "tcp", key.span)
            built += self.each({key.value: group}, key.value, partial(self.connection, kind=kind))
        return built

    def connection(self, obj: JObject, kind: ast.Ident) -> ast.ConnectionDecl | None:
        m = self.members(obj, "a connection", _CONNECTION)
        name = self.name(obj, m, "a connection")
        brace = self.opening(obj)
        baud = ast.IntLit(DEFAULT_BAUD, brace) if "baud" not in m else self.expr(m["baud"], "int")
        attrs: list[ast.ConnectionAttr | None] = [None if baud is None else ast.Baud(baud, baud.span)]
        if "dataBits" in m:
            bits = self.expr(m["dataBits"], "int")
            attrs.append(None if bits is None else ast.DataBits(bits, bits.span))
        if "parity" in m:
            parity = self.ident(m["parity"], "`parity`")
            attrs.append(None if parity is None else ast.Parity(parity, parity.span))
        if "stopBits" in m:
            bits = self.expr(m["stopBits"], "float")
            attrs.append(None if bits is None else ast.StopBits(bits, bits.span))
        threading = self.object(m.get("singleThreading"), "`singleThreading`")
        if threading is None:
            attrs.append(
                ast.Threading(ast.Ident("single", brace), ast.IntLit(DEFAULT_FREQUENCY_HZ, brace), brace)
            )
        else:
            t = self.members(threading, "`singleThreading`", ("freqHz",))
            hz = self.required(
                threading, t, "freqHz", "`singleThreading`", lambda v, _: self.expr(v, "float")
            )
            attrs.append(
                None if hz is None else ast.Threading(ast.Ident("single", threading.span), hz, threading.span)
            )
        for event in ("startup", "terminate", "keepalive"):
            hook = self.object(m.get(event), f"`{event}`")
            attrs.append(None if hook is None else self.hook(hook, event))
        terminator = self.string(m.get("terminator"), "`terminator`")
        if terminator is not None:
            attrs.append(ast.Terminator(ast.StrLit(terminator.value, terminator.span), terminator.span))
        address = self.string(m.get("address"), "`address`")
        if address is not None:
            attrs.append(ast.Address(ast.StrLit(address.value, address.span), address.span))
        if name is None:
            return None
        return ast.ConnectionDecl(name, kind, _present(attrs), obj.span, self.doc(m))

    def hook(self, obj: JObject, event: str) -> ast.Hook | None:
        keepalive = event == "keepalive"
        what = f"the `{event}` hook"
        m = self.members(obj, what, ("name", "interval", "arguments") if keepalive else ("name", "arguments"))
        target = self.name(obj, m, what)
        every = None
        if keepalive:
            interval = self.required(obj, m, "interval", what, lambda v, _: self.expr(v, "float"))
            every = None if interval is None else ast.Duration(interval, "ms", interval.span)
        if target is None:
            return None
        args = self.args(m.get("arguments"), self.interface_types.get(target.text, ()))
        return ast.Hook(event, ast.Call(target, args, obj.span), every, obj.span)

    def primitive(self, obj: JObject) -> ast.PrimitiveDecl | None:
        m = self.members(obj, "a primitive", _PRIMITIVE)
        name = self.name(obj, m, "a primitive")
        clauses: list[ast.PrimitiveClause] = []
        connection = self.ident(m["connection"], "`connection`") if "connection" in m else None
        if connection is not None:
            clauses.append(ast.On(connection, connection.span))
        lines = self.object(m.get("lines"), "`lines`")
        if lines is not None:  # {"dtr": "<not on>", "break": 10, ...}: in the order they are set, a break in ms
            settings: list[ast.Assign | ast.LineBreak] = []
            for line_name, value in lines.members:
                line = self.ident(line_name, "a modem line")
                level = self.expr(value, "float" if line is not None and line.text == "break" else "bool")
                if line is None or level is None:
                    continue
                settings.append(ast.LineBreak(ast.Duration(level, "ms", level.span), level.span)
                                if line.text == "break" else ast.Assign(line, level, level.span))
            clauses.append(ast.Lines(tuple(settings), lines.span))
        encodings = [(kind, s) for kind in ("pack", "format") if (s := self.string(m.get(kind), f"`{kind}`"))]
        slots = _slot_types(*encodings[0]) if encodings else {}
        written = self.array(m.get("formatArgs"), "`formatArgs`")
        args = _present([self.expr(a, slots.get(i)) for i, a in enumerate(written)])
        if written and not encodings:
            self.error(m["formatArgs"].span, "`formatArgs` without a `pack` or `format` to send them with")
        for kind, s in encodings:
            clauses.append(ast.Encoding(kind, ast.StrLit(s.value, s.span), args, s.span))
        for kind in ("unpack", "regex"):
            s = self.string(m.get(kind), f"`{kind}`")
            if s is not None:
                clauses.append(ast.Decoding(kind, ast.StrLit(s.value, s.span), s.span))
        marker = self.string(m.get("recordsUntil"), "`recordsUntil`")
        if marker is not None:
            clauses.append(ast.Records(ast.StrLit(marker.value, marker.span), marker.span))
        framed = self.framed(m.get("frame"))
        if framed is not None:
            clauses.append(framed)
        skip = m.get("skipUnmatched")
        if isinstance(skip, JBool) and skip.value:
            clauses.append(ast.SkipUnmatched(skip.span))
        if "timeout" in m:
            wait = self.expr(m["timeout"], "float")
            if wait is not None:
                clauses.append(ast.ReplyTimeout(ast.Duration(wait, "ms", wait.span), wait.span))
        if "retry" in m:
            count = self.expr(m["retry"], "int")
            if count is not None:
                clauses.append(ast.Retry(count, count.span))
        if "repliesEach" in m:
            each = self.replies_each(m["repliesEach"], m.get("replyFrames"))
            if each is not None:
                clauses.append(each)
        elif "replyFrames" in m:
            given = m.get("parameters")
            each = self.reply_frames(m["replyFrames"], {item.value for item in given.items if isinstance(item, JString)}
                                     if isinstance(given, JArray) else set())
            if each is not None:
                clauses.append(each)
        elif "replies" in m:
            count = self.expr(m["replies"], "int")
            if count is not None:
                clauses.append(ast.Replies(count, count.span))
        if "expect" in m:
            condition = self.reply_expr(m["expect"], "`expect`")
            if condition is not None:
                clauses.append(ast.Expect(condition, m["expect"].span))
        table = self.object(m.get("replyTable"), "`replyTable`")
        if table is not None:
            clauses.append(self.reply_table(table))
        if "replyList" in m:
            listed = _present([self.listed_reply(r) for r in self.array(m["replyList"], "`replyList`")])
            clauses.append(ast.ReplyList(tuple(listed), m["replyList"].span))
        if "error" in m:
            error = self.error_reply(m["error"])
            if error is not None:
                clauses.append(error)
        actions = self.array(m.get("postActions"), "`postActions`")
        if actions:  # none is the default, left unsaid
            assigns = _present([self.post_action(a) for a in actions])
            clauses.append(ast.Actions(assigns, m["postActions"].span))

        def infer(param: ast.Ident) -> str:
            bare = (
                i
                for i, a in enumerate(args)
                if isinstance(a, ast.Ref) and a.name == param.text and i in slots
            )
            return next((slots[i] for i in bare), "int")

        params = self.params(m, infer)
        if name is None:
            return None
        self.primitive_types[name.text] = tuple(_type_text(p.type) for p in params)
        return ast.PrimitiveDecl(name, params, tuple(clauses), obj.span, self.doc(m))

    def interface(self, obj: JObject) -> ast.InterfaceDecl | None:
        m = self.members(obj, "an interface", _INTERFACE)
        name = self.name(obj, m, "an interface")
        clauses: list[ast.InterfaceClause] = []
        kind = self.string(m.get("type"), "`type`")
        if kind is not None and kind.value not in ("adhoc", "periodic"):
            self.error(kind.span, f"an interface's `type` is `adhoc` or `periodic`, not {kind.raw}")
        elif kind is not None and kind.value == "periodic":  # adhoc is the default, left unsaid
            clauses.append(ast.Kind("periodic", kind.span))
        if "triggers" in m:  # an output's name, as in the thesis, or a list of them
            value = m["triggers"]
            items = self.array(value, "`triggers`") if isinstance(value, JArray) else [value]
            outputs = _present([self.ident(item, "`triggers`") for item in items])
            if outputs:
                clauses.append(ast.Triggers(tuple(outputs), value.span))
        calls = [
            self.object(item, "a primitive call")
            for item in self.array(m.get("primitiveCalls"), "`primitiveCalls`")
        ]
        body = _present([None if c is None else self.call_stmt(c) for c in calls])

        def infer(param: ast.Ident) -> str:
            for stmt in body:
                for arg, type_ in zip(stmt.call.args, self.primitive_types.get(stmt.call.target.text, ())):
                    if isinstance(arg, ast.Ref) and arg.name == param.text:
                        return type_
            return "float"

        params = self.params(m, infer)
        if "parameterTypes" not in m:  # thesis JSON, which ran on Python 2
            floats = {p.name.text for p in params if _type_text(p.type) == "float"}
            body = tuple(self.truncated(stmt, floats) for stmt in body)
        if name is None:
            return None
        self.interface_types[name.text] = tuple(_type_text(p.type) for p in params)
        return ast.InterfaceDecl(name, params, tuple(clauses), tuple(body), obj.span, self.doc(m))

    def truncated(self, stmt: ast.CallStmt, floats: set[str]) -> ast.CallStmt:
        """A call as the thesis ran it: Python 2's `struct` truncated a float packed with an
        integer code towards zero, so an argument that may be a float going into an int
        parameter is imported as `int(...)`, with a warning that shows it."""
        types = self.primitive_types.get(stmt.call.target.text, ())
        args = list(stmt.call.args)
        for i, (arg, type_) in enumerate(zip(args, types)):
            if type_ == "int" and _may_be_float(arg, floats):
                args[i] = ast.CallExpr(ast.Ident("int", arg.span), (arg,), arg.span)
                self.d.report("W403", arg.span, f"a float going into an int: imported as `{print_expr(args[i])}`, "
                              "towards zero, as Python 2's struct packed it for the thesis",
                              help="write `round(...)` instead if the device wants the nearest integer")
        if args == list(stmt.call.args):
            return stmt
        return dataclasses.replace(stmt, call=dataclasses.replace(stmt.call, args=tuple(args)))

    def call_stmt(self, obj: JObject) -> ast.CallStmt | None:
        m = self.members(obj, "a primitive call", _CALL)
        target = self.name(obj, m, "a primitive call")
        if target is None:
            return None
        args = self.args(m.get("arguments"), self.primitive_types.get(target.text, ()))
        delay = priority = None
        if "delay" in m and not _is_zero(m["delay"]):  # 0 is the default, left unsaid
            delay = self.expr(m["delay"], "float")
        if "priority" in m and not _is_zero(m["priority"]):
            priority = self.expr(m["priority"], "int")
        when = self.expr(m["when"], "bool") if "when" in m else None
        delays = _present([None if delay is None else ast.Duration(delay, "ms", delay.span)])
        return ast.CallStmt(ast.Call(target, args, obj.span), delays, _present([priority]), obj.span,
                            _present([when]), _present([self.poll(obj, m)]))

    def poll(self, obj: JObject, m: Members) -> ast.Poll | None:
        """`"until"`, `"every"` and `"within"` (ms), together: the call's `until COND every P within T`."""
        if "until" not in m:
            return None
        until = self.expr(m["until"], "bool")
        every = self.expr(m["every"], "float") if "every" in m else None
        within = self.expr(m["within"], "float") if "within" in m else None
        if every is None or within is None:
            self.d.report("E008", obj.span, "a call with `until` gives `every` and `within` (ms)")
            return None
        if until is None:
            return None
        return ast.Poll(until, ast.Duration(every, "ms", every.span), ast.Duration(within, "ms", within.span), obj.span)

    def adapter(self, obj: JObject) -> ast.AdapterDecl | None:
        m = self.members(obj, "an adapter", _ADAPTER)
        name = self.name(obj, m, "an adapter")
        ros = self.string(m.get("ros"), "`ros`")
        objects = [self.object(item, "an adapter field") for item in self.array(m.get("fields"), "`fields`")]
        built = _present([None if f is None else self.field(f) for f in objects])
        if name is None:
            return None
        self.adapter_fields[name.text] = {f.name.text: _type_text(f.type) for f in built}
        return ast.AdapterDecl(name, _str_lit(ros), built, obj.span, self.doc(m))

    def field(self, obj: JObject) -> ast.FieldDecl | None:
        m = self.members(obj, "an adapter field", _FIELD)
        name = self.name(obj, m, "an adapter field")
        type_ = self.required(obj, m, "type", "an adapter field", self.type_ref)
        unit, ros = self.string(m.get("unit"), "`unit`"), self.string(m.get("ros"), "`ros`")
        if name is None or type_ is None:
            return None
        return ast.FieldDecl(name, type_, _text(unit), _str_lit(ros), obj.span, self.doc(m))

    def input(self, obj: JObject) -> ast.InputDecl | None:
        m = self.members(obj, "a domain interface", _INPUT)
        name = self.name(obj, m, "a domain interface")
        params = [
            i for v in self.array(m.get("parameters"), "`parameters`") if (i := self.ident(v, "a parameter"))
        ]
        calls = self.required(obj, m, "calls", "a domain interface", self.object)
        if name is None or calls is None:
            return None
        c = self.members(calls, "`calls`", ("name", "arguments"))
        target = self.name(calls, c, "`calls`")
        if target is None:
            return None
        args = self.args(c.get("arguments"), self.interface_types.get(target.text, ()))
        adapter = self.adapter_of(obj, m, name, params, ordered=True)
        call = ast.Call(target, args, calls.span)
        return ast.InputDecl(name, adapter, call, obj.span, self.doc(m))

    def output(self, obj: JObject) -> ast.OutputDecl | None:
        m = self.members(obj, "a domain output", _OUTPUT)
        name = self.name(obj, m, "a domain output")
        returns = self.required(obj, m, "returns", "a domain output", self.object)
        if name is None or returns is None:
            return None
        written = [
            (field_, value) for key, value in returns.members if (field_ := self.ident(key, "a field"))
        ]
        adapter = self.adapter_of(obj, m, name, [field_ for field_, _ in written])
        types = self.adapter_fields.get(adapter.text, {})
        assigns = []
        for field_, value in written:
            expr = self.expr(value, types.get(field_.text))
            assigns.append(None if expr is None else ast.Assign(field_, expr, value.span))
        frame = None if "frame" not in m else self.ident(m["frame"], "`frame`")
        return ast.OutputDecl(name, adapter, _present(assigns), obj.span, self.doc(m), frame)

    # -- the body: the RDIS clauses its members stand for, checked by the checker --

    def link(self, obj: JObject) -> ast.LinkDecl | None:
        m = self.members(obj, "a link", _LINK)
        name = self.name(obj, m, "a link")
        items: list[ast.ShapeUse | ast.BodyValue | None] = []
        for role, key in (("visual", "visuals"), ("collision", "collisions")):
            shapes = [self.object(item, f"a {role} shape") for item in self.array(m.get(key), f"`{key}`")]
            items += [None if o is None else self.shape_use(o, role) for o in shapes]
        inertial = self.object(m.get("inertial"), "`inertial`")
        if inertial is not None:
            i = self.members(inertial, "`inertial`", _INERTIAL)
            items += [self.body_value(i, key, key) for key in _INERTIAL]
        if name is None:
            return None
        return ast.LinkDecl(name, _present(items), obj.span, self.doc(m))

    def shape_use(self, obj: JObject, role: str) -> ast.ShapeUse | None:
        """`{"shape": "box", "size": [x, y, z]}` is `box(x, y, z)`; `{"shape": "mesh", "path": "f.stl",
        "scale": [1, 1, 1]}` is `mesh("f.stl", [1, 1, 1])`."""
        what = f"a {role} shape"
        s = self.members(obj, what, _SHAPE)
        kind = self.required(obj, s, "shape", what, self.ident)
        path = self.string(s.get("path"), "`path`")
        args: list[ast.Expr | None] = [] if path is None else [ast.StrLit(path.value, path.span)]
        args += [self.expr(v, "float") for v in self.array(s.get("size"), "`size`")]
        if "scale" in s:
            args.append(self.expr(s["scale"], "float"))
        at = self.expr(s["xyz"], "float") if "xyz" in s else None
        rpy = self.expr(s["rpy"], "float") if "rpy" in s else None
        if kind is None:
            return None
        return ast.ShapeUse(role, ast.Shape(kind, _present(args), obj.span), at, rpy, obj.span)

    def body_value(self, m: Members, key: str, word: str) -> ast.BodyValue | None:
        """The member `key`, when given, as the clause `word VALUE`."""
        value = self.expr(m[key], "float") if key in m else None
        return None if value is None else ast.BodyValue(word, value, m[key].span)

    def joint(self, obj: JObject) -> ast.JointDecl | None:
        m = self.members(obj, "a joint", _JOINT)
        name = self.name(obj, m, "a joint")
        kind = self.required(obj, m, "type", "a joint", self.ident)
        parent = self.required(obj, m, "parent", "a joint", self.ident)
        child = self.required(obj, m, "child", "a joint", self.ident)
        items: list[ast.BodyValue | ast.JointLimit | None] = [
            self.body_value(m, "xyz", "at"), self.body_value(m, "rpy", "rpy"), self.body_value(m, "axis", "axis")]
        if "limit" in m:
            bounds = self.array(m["limit"], "a joint's limit")
            if len(bounds) == 2:
                low, high = self.expr(bounds[0], "float"), self.expr(bounds[1], "float")
                items.append(None if low is None or high is None else ast.JointLimit(low, high, m["limit"].span))
            elif isinstance(m["limit"], JArray):
                self.error(m["limit"].span, "a joint's limit is `[low, high]`")
        items += [self.body_value(m, key, key) for key in ("velocity", "effort", "damping", "friction")]
        if name is None or kind is None or parent is None or child is None:
            return None
        return ast.JointDecl(name, kind, parent, child, _present(items), obj.span, self.doc(m))

    def transmission(self, obj: JObject) -> ast.TransmissionDecl | None:
        m = self.members(obj, "a transmission", _TRANSMISSION)
        name = self.name(obj, m, "a transmission")
        joint = self.required(obj, m, "joint", "a transmission", self.ident)
        bindings: list[ast.Binding | None] = []
        for role, key in (("command", "commands"), ("measure", "measures")):
            objects = [self.object(item, f"a {role}") for item in self.array(m.get(key), f"`{key}`")]
            bindings += [None if o is None else self.binding(o, role) for o in objects]
        if name is None or joint is None:
            return None
        return ast.TransmissionDecl(name, joint, _present(bindings), obj.span, self.doc(m))

    def binding(self, obj: JObject, role: str) -> ast.Binding | None:
        """A command names its `primitive` or its `interface` and the `parameter`; a measure its `state`.
        `toDevice` and `toJoint` are the conversions `raw = ...` and `QUANTITY = ...`."""
        what = f"a {role}"
        b = self.members(obj, what, _COMMAND if role == "command" else _MEASURE)
        quantity = self.required(obj, b, "quantity", what, self.ident)
        member = None
        if role == "command":
            kinds = [k for k in ("primitive", "interface") if k in b]
            if len(kinds) != 1:
                self.error(self.opening(obj), "a command names one `primitive` or one `interface`")
                return None
            target = self.ident(b[kinds[0]], f"`{kinds[0]}`")
            other = "interface" if kinds[0] == "primitive" else "primitive"
            known = self.primitive_types if other == "primitive" else self.interface_types
            mine = self.interface_types if other == "primitive" else self.primitive_types
            if target is not None and target.text in known and target.text not in mine:
                self.error(b[kinds[0]].span, f"`{target.text}` is {'an' if other == 'interface' else 'a'} {other}",
                           help=f"write `\"{other}\": \"{target.text}\"`")
                return None
            member = self.required(obj, b, "parameter", what, self.ident)
        else:
            target = self.required(obj, b, "state", what, self.ident)
        index = self.expr(b["index"], "int") if "index" in b else None
        to_device = self.required(obj, b, "toDevice", what, lambda v, _: self.expr(v, None))
        to_joint = self.required(obj, b, "toJoint", what, lambda v, _: self.expr(v, None))
        if quantity is None or target is None or to_device is None or to_joint is None \
                or (role == "command" and member is None) or ("index" in b and index is None):
            return None
        conversions = (ast.Assign(ast.Ident("raw", to_device.span), to_device, b["toDevice"].span),
                       ast.Assign(ast.Ident(quantity.text, to_joint.span), to_joint, b["toJoint"].span))
        return ast.Binding(role, quantity, target, member, index, conversions, obj.span)

    def adapter_of(self, obj: JObject, m: Members, element: ast.Ident, names: list[ast.Ident],
                   ordered: bool = False) -> ast.Ident:
        """The adapter named, else the standard one with exactly these fields, else a new one.
        Where the order of the fields is the element's (an input's parameters), a standard
        adapter with them in another order is copied in this order: its units and ROS paths
        kept, and the parameters' order kept through `rdisc build`."""
        if "adapter" in m:
            return self.ident(m["adapter"], "`adapter`") or ast.Ident("", m["adapter"].span)
        wanted = [n.text for n in names]
        standard = next((a for a in self.standard.values() if {f.name.text for f in a.fields} == set(wanted)), None)
        if standard is not None and (not ordered or [f.name.text for f in standard.fields] == wanted):
            return ast.Ident(standard.name.text, self.opening(obj))
        base = "".join(part[:1].upper() + part[1:] for part in element.text.split("_")) + "Message"
        made, n = base, 2
        while made in self.adapter_fields:
            made, n = f"{base}{n}", n + 1
        if standard is not None:
            by_name = {f.name.text: f for f in standard.fields}
            decl_fields = tuple(dataclasses.replace(by_name[f.text], span=f.span) for f in names)
            doc = f"{standard.name.text}, with its fields in the order of `{element.text}`."
            decl = ast.AdapterDecl(ast.Ident(made, element.span), standard.ros, decl_fields, obj.span, doc)
        else:
            decl_fields = tuple(ast.FieldDecl(f, ast.Ident("float", f.span), None, None, f.span) for f in names)
            decl = ast.AdapterDecl(ast.Ident(made, element.span), None, decl_fields, obj.span)
        self.made_adapters.append(decl)
        self.adapter_fields[made] = {f.name.text: _type_text(f.type) for f in decl_fields}
        return ast.Ident(made, element.span)

    # -- parameters, arguments and expressions --

    def params(self, m: Members, infer: Callable[[ast.Ident], str]) -> tuple[ast.Param, ...]:
        names = [
            i for v in self.array(m.get("parameters"), "`parameters`") if (i := self.ident(v, "a parameter"))
        ]
        ranges = self.ranges(m, len(names))
        defaults = self.defaults(m, len(names))
        units = self.units(m, len(names))
        if "parameterTypes" not in m:
            return tuple(ast.Param(n, ast.Ident(infer(n), n.span), n.span, *r, d, u)
                         for n, r, d, u in zip(names, ranges, defaults, units))
        types = [
            t for v in self.array(m["parameterTypes"], "`parameterTypes`") if (t := self.type_ref(v, "a type"))
        ]
        if len(types) != len(names):
            self.error(
                m["parameterTypes"].span,
                f"`parameterTypes` has {len(types)} entries for {len(names)} parameters",
            )
            return ()
        return tuple(ast.Param(n, t, n.span, *r, d, u) for n, t, r, d, u in zip(names, types, ranges, defaults, units))

    def units(self, m: Members, count: int) -> list[ast.StrLit | None]:
        """`parameterUnits`: a unit or null for each parameter."""
        if "parameterUnits" not in m:
            return [None] * count
        items = self.array(m["parameterUnits"], "`parameterUnits`")
        if len(items) != count:
            self.error(m["parameterUnits"].span, f"`parameterUnits` has {len(items)} entries for {count} parameters")
            return [None] * count
        return [None if isinstance(item, JNull) else _str_lit(self.string(item, "a parameter's unit")) for item in items]

    def defaults(self, m: Members, count: int) -> list[ast.Expr | None]:
        """`parameterDefaults`: a value or null for each parameter."""
        if "parameterDefaults" not in m:
            return [None] * count
        items = self.array(m["parameterDefaults"], "`parameterDefaults`")
        if len(items) != count:
            self.error(m["parameterDefaults"].span,
                       f"`parameterDefaults` has {len(items)} entries for {count} parameters")
            return [None] * count
        return [None if isinstance(item, JNull) else self.expr(item, None) for item in items]

    def ranges(self, m: Members, count: int) -> list[tuple[ast.Expr | None, ast.Expr | None]]:
        """`parameterRanges`: `[low, high]` or null for each parameter."""
        none: tuple[ast.Expr | None, ast.Expr | None] = (None, None)
        if "parameterRanges" not in m:
            return [none] * count
        items = self.array(m["parameterRanges"], "`parameterRanges`")
        if len(items) != count:
            self.error(m["parameterRanges"].span, f"`parameterRanges` has {len(items)} entries for {count} parameters")
            return [none] * count
        built = []
        for item in items:
            bounds = () if isinstance(item, JNull) else self.array(item, "a parameter's range")
            if len(bounds) == 2:
                built.append((self.expr(bounds[0], None), self.expr(bounds[1], None)))
            else:
                if not isinstance(item, JNull):
                    self.error(item.span, "a parameter's range is `[low, high]` or null")
                built.append(none)
        return built

    def args(self, value: JValue | None, types: tuple[str, ...]) -> tuple[ast.Expr, ...]:
        items = self.array(value, "`arguments`")
        return _present([self.expr(a, types[i] if i < len(types) else None) for i, a in enumerate(items)])

    def expr(self, v: JValue, type_: str | None) -> ast.Expr | None:
        """An expression: a JSON literal, `""` (the default of `type_`), `"<expr>"`, or a string."""
        match v:
            case JBool(value, span):
                return ast.BoolLit(value, span)
            case JNumber(value, span):
                return _number(value, span)
            case JString("", _, span):
                return _literal(_DEFAULTS.get(type_ or "", ""), span)
            case JString(value, _, span) if not _embedded(value):
                return ast.StrLit(value, span)
            case JString():
                offsets = self.offsets(v)
                return self.parse(v.value[1:-1], offsets[1 : len(v.value)])
            case JArray(items, span) if items:  # a constant array: `"IDS": [1, 2, 3]`
                values = [self.expr(item, None) for item in items]
                built = tuple(value for value in values if value is not None)
                return ast.ArrayLit(built, span) if len(built) == len(values) else None
        self.error(v.span, f"expected an expression (a number, true/false, a string or an array), found {_kind(v)}")
        return None

    def replies_each(self, v: JValue, frames: JValue | None) -> ast.Replies | None:
        """`"repliesEach": {"variable": "id", "over": "ids"}` with its one reply frame in
        `"replyFrames"`, its arguments reading the variable: `replies id in ids frame status(id)`."""
        obj = self.object(v, "`repliesEach`")
        if obj is None:
            return None
        given = self.members(obj, "`repliesEach`", ("variable", "over"))
        var, over = (self.required(obj, given, key, "`repliesEach`", self.ident) for key in ("variable", "over"))
        listed = self.array(frames, "`replyFrames`") if frames is not None else []
        if len(listed) != 1:
            self.error(obj.span, "`repliesEach` reads every reply through one frame: `replyFrames` lists it alone")
            return None
        framed = self.framed(listed[0])
        if var is None or over is None or framed is None:
            return None
        return ast.Replies(ast.Ref(over.text, over.span), obj.span, var, None, framed)

    def reply_frames(self, v: JValue, params: set[str]) -> ast.Replies | None:
        """`"replyFrames"`, each reply's frame written out, as `replies reply in 0..N-1 frame
        NAME(args)`: an argument that differs between replies is `[a0, a1, ...][reply]`."""
        objects = [f for f in self.array(v, "`replyFrames`") if isinstance(f, JObject)]
        frames = [self.members(f, "a reply frame", ("name", "arguments")) for f in objects]
        names = {self.name(obj, f, "a reply frame") for obj, f in zip(objects, frames)}
        if len(frames) < 2 or len(names) != 1 or None in names:
            self.error(v.span, "`replyFrames` names one frame, for each of two replies or more")
            return None
        frame = names.pop()
        assert frame is not None
        rows = [self.args(f.get("arguments"), self.frame_types.get(frame.text, ())) for f in frames]
        if len({len(row) for row in rows}) != 1:
            self.error(v.span, "every reply frame of `replyFrames` takes as many arguments")
            return None
        var = ast.Ident(next(n for n in ("reply", "reply_", "reply__", "reply_n") if n not in params), v.span)
        ref = ast.Ref(var.text, v.span)
        columns = list(zip(*rows))
        varying = [c for c in columns if len({print_expr(a) for a in c}) > 1]
        # Elements of array parameters, as written (`ids[i]`), so that build and import in turn
        # do not grow them: the range starts where their indexes do, when they all start at one.
        indexed = {id(c): found for c in varying if (found := _indexed(c)) is not None}
        starts = {start for _, start in indexed.values()}
        start = starts.pop() if len(starts) == 1 and len(indexed) == len(varying) else 0
        args = [column[0] if column not in varying
                else ast.Index(indexed[id(column)][0], ref, v.span)
                if id(column) in indexed and indexed[id(column)][1] == start
                else ast.Index(ast.ArrayLit(column, v.span), ref, v.span)
                for column in columns]
        framed = ast.Framed(frame, tuple(args), v.span)
        return ast.Replies(ast.IntLit(start, v.span), v.span, var, ast.IntLit(start + len(rows) - 1, v.span), framed)

    def reply_expr(self, v: JValue, what: str) -> ast.Expr | None:
        """`"<expr>"` over the reply, called `__out__` as in post-actions."""
        s = self.string(v, what)
        if s is None:
            return None
        text, offsets = s.value, self.offsets(s)
        if _embedded(text):
            text, offsets = text[1:-1], offsets[1 : len(text)]
        text, offsets = _reply_as_out(text, offsets)
        return self.parse(text, offsets)

    def post_action(self, v: JValue) -> ast.Assign | None:
        """`"state = expr"` or `"state[index] = expr"` (or inside `<...>`), with the reply as `__out__`."""
        s = self.string(v, "a post-action")
        if s is None:
            return None
        text, offsets = s.value, self.offsets(s)
        if _embedded(text):
            text, offsets = text[1:-1], offsets[1 : len(text)]
        m = _ASSIGNMENT.match(text) or _ELEMENT_ASSIGNMENT.match(text)
        if m is None or not _NAME.fullmatch(m.group(1)):
            self.error(
                s.span,
                "a post-action is written `state = expression`",
                help='e.g. "bumperStates = __out__[0]"',
            )
            return None
        target = ast.Ident(m.group(1), Span(self.path, offsets[m.start(1)], offsets[m.end(1)]))
        index = None
        if m.re is _ELEMENT_ASSIGNMENT:
            at, end = m.start(2), m.end(2)
            index = self.parse(*_reply_as_out(text[at:end], offsets[at : end + 1]))
            if index is None:
                return None
        text, offsets = _reply_as_out(text[m.end() :], offsets[m.end() :])
        when = None
        split = _WHEN.search(text)  # `value when COND`: the last `when` of the text
        if split is not None:
            when = self.parse(text[split.end():], offsets[split.end():])
            if when is None:
                return None
            text, offsets = text[: split.start()], offsets[: split.start() + 1]
        value = self.parse(text, offsets)
        return None if value is None else ast.Assign(target, value, s.span, index, when)

    def offsets(self, s: JString) -> list[int]:
        """The file offset of each character of a decoded string, then of its closing quote."""
        if "\\" not in s.raw:
            return list(range(s.span.start + 1, s.span.end))
        return [s.span.start + m.start() for m in _JSON_CHAR.finditer(s.raw, 1, len(s.raw) - 1)] + [
            s.span.end - 1
        ]

    def parse(self, text: str, offsets: list[int]) -> ast.Expr | None:
        """Parse `text`, whose character i is at file offset offsets[i]."""
        if offsets[-1] - offsets[0] == len(text):  # written as is: spans are a plain shift
            return parse_expression(self.path, text, offsets[0], self.d)
        local = Diagnostics()
        expr = parse_expression(self.path, text, 0, local)

        def place(span: Span) -> Span:
            return Span(self.path, offsets[span.start], offsets[span.end])

        for d in local.items:
            labels = tuple(Label(place(label.span), label.message) for label in d.labels)
            span = None if d.span is None else place(d.span)
            self.d.report(d.code, span, d.message, label=d.label, labels=labels, help=d.help)
        return None if expr is None else _respan(expr, place)

    # -- members of the expected kinds --

    def error(self, span: Span, message: str, help: str | None = None) -> None:
        self.d.report("E008", span, message, help=help)

    def opening(self, obj: JObject) -> Span:
        """The `{` of an object: where a member it lacks is reported."""
        return Span(self.path, obj.span.start, obj.span.start + 1)

    def members(self, obj: JObject, what: str, known: tuple[str, ...]) -> Members:
        found: Members = {}
        for key, value in obj.members:
            if key.value in known:
                found[key.value] = value
                continue
            close = difflib.get_close_matches(key.value, known, n=1)
            hint = (
                f"did you mean `{close[0]}`?"
                if close
                else "known members: " + ", ".join(f"`{k}`" for k in known)
            )
            self.error(key.span, f"unknown member `{key.value}` in {what}", help=hint)
        return found

    def required(
        self, obj: JObject, m: Members, key: str, what: str, get: Callable[[JValue, str], _Built]
    ) -> _Built | None:
        if key not in m:
            self.error(self.opening(obj), f"{what} has no `{key}`")
            return None
        return get(m[key], f"`{key}`")

    def name(self, obj: JObject, m: Members, what: str) -> ast.Ident | None:
        return self.required(obj, m, "name", what, self.ident)

    def type_ref(self, v: JValue, what: str) -> ast.TypeRef | None:
        """A type's name, or an array type: `"int[6]"`, `"float[]"` (an adapter's field)."""
        s = self.string(v, what)
        if s is not None and (array := _ARRAY_TYPE.fullmatch(s.value)) is not None:
            start = s.span.start + 1  # after the opening quote: the name is written as is
            element = ast.Ident(array.group(1), Span(self.path, start, start + len(array.group(1))))
            size = None if not array.group(2) else ast.IntLit(int(array.group(2)), s.span)
            return ast.ArrayOf(element, size, s.span)
        return self.ident(v, what)

    def ident(self, v: JValue, what: str) -> ast.Ident | None:
        s = self.string(v, what)
        if s is None:
            return None
        if not _NAME.fullmatch(s.value):
            self.error(
                s.span, f"{what} must be a name (a letter, then letters, digits or `_`), found {s.raw}"
            )
            return None
        return ast.Ident(s.value, self.inner(s))

    def inner(self, s: JString) -> Span:
        """The characters between the quotes, when they are written as is."""
        return s.span if "\\" in s.raw else Span(self.path, s.span.start + 1, s.span.end - 1)

    def string(self, v: JValue | None, what: str) -> JString | None:
        return self.expect(v, JString, what, "a string")

    def object(self, v: JValue | None, what: str) -> JObject | None:
        return self.expect(v, JObject, what, "an object")

    def array(self, v: JValue | None, what: str) -> tuple[JValue, ...]:
        found = self.expect(v, JArray, what, "an array")
        return () if found is None else found.items

    def expect(self, v: JValue | None, kind: type[_Kind], what: str, words: str) -> _Kind | None:
        if v is None or isinstance(v, kind):
            return v
        self.error(v.span, f"{what} must be {words}, found {_kind(v)}")
        return None

    def doc(self, m: Members) -> str | None:
        """A doc text as the parser would read it back from `///` lines."""
        s = self.string(m.get("doc"), "`doc`")
        return None if s is None else "\n".join(line.rstrip() for line in s.value.split("\n")).strip()


# ---- helpers -------------------------------------------------------------------------------

# One character of a JSON string body: a surrogate pair escape decodes to one character.
_JSON_CHAR = re.compile(
    r"\\u[dD][89abAB][0-9a-fA-F]{2}\\u[dD][c-fC-F][0-9a-fA-F]{2}|\\u[0-9a-fA-F]{4}|\\.|.", re.DOTALL
)
_ASSIGNMENT = re.compile(r"\s*([A-Za-z_]\w*)\s*=(?!=)")
_ELEMENT_ASSIGNMENT = re.compile(r"\s*([A-Za-z_]\w*)\[([^=]*)\]\s*=(?!=)")  # `position[id] = ...`
# `__out__` as an identifier; string literals are matched (and skipped) so that their text is left alone.
_OUT = re.compile(r'r?"(?:[^"\\\n]|\\.)*"|(?<![A-Za-z0-9_])(__out__)(?![A-Za-z0-9_])')


def _indexed(column: tuple[ast.Expr, ...]) -> tuple[ast.Ref, int] | None:
    """`a[K], a[K+1], ..., a[K+N-1]`: (`a`, K), a reply frame's argument written from an array
    parameter by the loop variable, which import writes back as `a[var]`."""
    first = column[0]
    if not (isinstance(first, ast.Index) and isinstance(first.base, ast.Ref) and isinstance(first.index, ast.IntLit)):
        return None
    name, start = first.base.name, first.index.value
    for number, arg in enumerate(column, start):
        if not (isinstance(arg, ast.Index) and isinstance(arg.base, ast.Ref) and arg.base.name == name
                and isinstance(arg.index, ast.IntLit) and arg.index.value == number):
            return None
    return first.base, start


def _keys(value: JValue | None) -> set[str]:
    """The member names of a JSON object; none of anything else."""
    return {key.value for key, _ in value.members} if isinstance(value, JObject) else set()


def _present(items: list[Any]) -> tuple[Any, ...]:
    """The items built; a missing one was reported, and `each` leaves its element out."""
    return tuple(x for x in items if x is not None)


def _text(s: JString | None) -> str | None:
    return None if s is None else s.value


def _str_lit(s: JString | None) -> ast.StrLit | None:
    return None if s is None else ast.StrLit(s.value, s.span)


def _embedded(value: str) -> bool:
    return len(value) >= 3 and value[0] == "<" and value[-1] == ">"


def _may_be_float(e: ast.Expr, floats: set[str]) -> bool:
    """Whether an expression of thesis JSON, whose float names are `floats`, may be a float
    (the checker decides for sure; this front end only decides what to convert)."""
    match e:
        case ast.FloatLit():
            return True
        case ast.Ref(name=name):
            return name in floats
        case ast.Unary(op=op, operand=operand):
            return op in "+-" and _may_be_float(operand, floats)
        case ast.BinOp(op="/"):
            return True
        case ast.BinOp(op=op, left=left, right=right) if op in ("+", "-", "*", "//", "%", "**"):
            return _may_be_float(left, floats) or _may_be_float(right, floats)
        case ast.Conditional(then=then, orelse=orelse):
            return _may_be_float(then, floats) or _may_be_float(orelse, floats)
        case ast.CallExpr(func=func, args=args):
            if func.text in FLOAT_FUNCTIONS or (func.text == "round" and len(args) == 2):
                return True
            return func.text in ("abs", "min", "max", "clamp") and any(_may_be_float(a, floats) for a in args)
    return False


def _is_zero(v: JValue) -> bool:
    return isinstance(v, JNumber) and v.value == 0


def _number(value: float, span: Span) -> ast.Expr:
    """A JSON number as the parser would read it: a negative one is a unary minus."""
    if value < 0 or str(value).startswith("-"):
        return ast.Unary("-", _literal(-value, Span(span.path, span.start + 1, span.end)), span)
    return _literal(value, span)


def _literal(value: Any, span: Span) -> ast.Expr:
    if isinstance(value, bool):
        return ast.BoolLit(value, span)
    if isinstance(value, int):
        return ast.IntLit(value, span)
    if isinstance(value, float):
        return ast.FloatLit(value, span)
    if isinstance(value, bytes):
        return ast.BytesLit(value, span)
    return ast.StrLit(value, span)


def _slot_types(kind: str, template: JString) -> dict[int, str]:
    """The type each format argument takes, by position: struct codes for `pack`;
    for `format`, the spec's type (e/f/g/% float, anything else int)."""
    try:
        if kind == "pack":
            return {i: slot.type.value for i, slot in enumerate(formats.struct_layout(template.value).slots)}
        specs = formats.format_fields(template.value)
    except formats.TemplateError:  # the checker reports it; nothing to infer from
        return {}
    return {i: "float" if f.spec[-1:] and f.spec[-1] in _FLOAT_SPECS else "int" for i, f in enumerate(specs)}


_WHEN = re.compile(r"\s+when\s+(?!.*\swhen\s)", re.DOTALL)


def _reply_as_out(text: str, offsets: list[int]) -> tuple[str, list[int]]:
    """Replace the identifier `__out__` by `out`, keeping each character's file offset."""
    pieces, places, last = [], [], 0
    for m in _OUT.finditer(text):
        if m.group(1) is None:
            continue
        pieces.append(text[last : m.start()] + "out")
        places += offsets[last : m.start() + 3]
        last = m.end()
    return "".join(pieces) + text[last:], places + offsets[last:]


def _respan(node: Any, place: Callable[[Span], Span]) -> Any:
    """A copy of an AST node with every span moved by `place`."""
    if isinstance(node, Span):
        return place(node)
    if isinstance(node, tuple):
        return tuple(_respan(x, place) for x in node)
    if is_dataclass(node) and not isinstance(node, type):
        return replace(node, **{f.name: _respan(getattr(node, f.name), place) for f in fields(node)})
    return node


def _part_name(part: JObject | None) -> str:
    """The name a checksum's `over` gives a frame part."""
    for key, value in part.members if part else ():
        if key.value in _BYTES_ROLES or key.value in ("length", "payload"):
            return key.value
        if key.value == "field" and isinstance(value, JString):
            return value.value
        if key.value == "fields" and isinstance(value, JArray):  # a `bits` part: any of its fields names it
            names = [_part_name(f) if isinstance(f, JObject) else "" for f in value.items]
            return "length" if "length" in names else next(iter(names), "checksum")
    return "checksum"
