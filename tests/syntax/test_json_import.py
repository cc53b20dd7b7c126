"""JSON import: thesis-style and canonical JSON to AST, spans into the JSON, E008s."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_path
from rdisc.diagnostics import Diagnostics
from rdisc.json_import.document import read
from rdisc.json_import.values import MAX_DEPTH, MAX_VALUES
from rdisc.source import SourceFile
from rdisc.syntax import ast
from rdisc.syntax.printer import print_module

DATA = Path(__file__).resolve().parent / "data"
ROOT = Path(__file__).resolve().parents[2]


def imported(text: str) -> tuple[ast.Module | None, Diagnostics]:
    diagnostics = Diagnostics()
    return read("t.json", text, diagnostics), diagnostics


def printed(document: dict) -> str:
    module, diagnostics = imported(json.dumps(document, indent=2))
    assert module is not None and not diagnostics.items, diagnostics.items
    return print_module(module)


def decl(module: ast.Module, kind: type, name: str):
    return next(d for d in module.decls if isinstance(d, kind) and d.name.text == name)


def test_thesis_appendix_b() -> None:
    """Appendix B with the expressions PDF extraction lost restored."""
    source = DATA / "thesis_create.json"
    module, diagnostics = imported(source.read_text(encoding="utf-8"))
    assert [(d.code, d.message) for d in diagnostics.items] == [
        ("W403", (f"a float going into an int: imported as `int({name} * 1000)`, towards zero, as Python 2's struct "
                 "packed it for the thesis")) for name in ("velocity", "radius")]
    assert print_module(module) == (DATA / "thesis_create.rdis").read_text(encoding="utf-8")


def test_spans_point_into_the_json() -> None:
    text = (DATA / "thesis_create.json").read_text(encoding="utf-8")
    module, _ = imported(text)
    body = decl(module, ast.InterfaceDecl, "drive").body[0]
    truncated = body.call.args[0]  # int(...), as Python 2 packed the float: spanning what it converts
    assert isinstance(truncated, ast.CallExpr) and truncated.func.text == "int"
    product = truncated.args[0]
    assert isinstance(product, ast.BinOp) and truncated.span == product.span
    assert text[product.span.start : product.span.end] == "velocity * 1000"
    assert text[product.left.span.start : product.left.span.end] == "velocity"
    assert SourceFile("t.json", text).position(product.span.start).line + 1 == 31
    (assign,) = next(
        c for c in decl(module, ast.PrimitiveDecl, "bumpers").clauses if isinstance(c, ast.Actions)
    ).assigns
    assert isinstance(assign.value, ast.Index)
    assert text[assign.value.base.span.start : assign.value.base.span.end] == "__out__"
    assert text[assign.value.span.start : assign.value.span.end] == "__out__[0]"
    assert text[assign.target.span.start : assign.target.span.end] == "bumperStates"
    name = decl(module, ast.PrimitiveDecl, "drive").name
    assert text[name.span.start : name.span.end] == "drive"


def test_spans_through_escapes() -> None:
    text = (
        r'{"name": "r", "stateVariables": [{"name": "s", "type": "string", "value": "<\"a\u0009b\" + x>"}]}'
    )
    module, diagnostics = imported(text)
    assert not diagnostics.items
    init = decl(module, ast.StateDecl, "s").init
    assert isinstance(init, ast.BinOp) and init.left == ast.StrLit("a\tb")
    assert text[init.left.span.start : init.left.span.end] == r"\"a\u0009b\""
    assert text[init.right.span.start : init.right.span.end] == "x"


def test_errors_inside_escaped_expressions_point_at_the_json() -> None:
    text = '{"name": "r", "stateVariables": [{"name": "s", "type": "int", "value": "<\\"\\u00e9\\" + >"}]}'
    _, diagnostics = imported(text)
    (d,) = diagnostics.items
    assert d.code == "E001" and d.message == "expected an expression, found the end of the expression"
    assert text[d.span.start] == ">"


PRIMITIVE_TYPES = [
    (">Bhh", ["<137>", "<a>", "<b>"], "pack", ["a", "b"], "int int"),
    ("<Bfd?", ["<1>", "<a>", "<b>", "<c>"], "pack", ["a", "b", "c"], "float float bool"),
    ("B3s", ["<1>", "<a>"], "pack", ["a"], "string"),
    ("D,{},{:.2f}\n", ["<a>", "<b>"], "format", ["a", "b"], "int float"),
    ("D,{1:x},{0:e}\n", ["<b>", "<a * 2>"], "format", ["b", "a"], "float int"),
    ("D,{:s},{:%}", ["<a>", "<b>"], "format", ["a", "b"], "int float"),
    (">h", ["<a + 1>"], "pack", ["a"], "int"),  # not passed bare: int
    ("{", ["<a>"], "format", ["a"], "int"),  # template broken: the checker reports it
]


@pytest.mark.parametrize(("template", "args", "kind", "params", "types"), PRIMITIVE_TYPES)
def test_primitive_parameter_types_are_inferred(template, args, kind, params, types) -> None:
    document = {
        "name": "r",
        "primitives": [{"name": "p", "parameters": params, "formatArgs": args, kind: template}],
    }
    module, diagnostics = imported(json.dumps(document))
    assert not diagnostics.items
    assert " ".join(p.type.text for p in decl(module, ast.PrimitiveDecl, "p").params) == types


def test_interface_parameter_types_are_inferred() -> None:
    document = {
        "name": "r",
        "primitives": [{"name": "p", "parameters": ["n", "x"], "formatArgs": ["<n>", "<x>"], "pack": "<Bf"}],
        "interfaces": [
            {
                "name": "i",
                "parameters": ["a", "b", "c"],
                "primitiveCalls": [{"name": "p", "arguments": ["<b>", "<a>"]}],
            },
            {"name": "j", "parameters": ["a"], "parameterTypes": ["string"], "primitiveCalls": []},
        ],
    }
    module, diagnostics = imported(json.dumps(document))
    assert not diagnostics.items
    assert [p.type.text for p in decl(module, ast.InterfaceDecl, "i").params] == ["float", "int", "float"]
    assert [p.type.text for p in decl(module, ast.InterfaceDecl, "j").params] == ["string"]


def test_literals_defaults_and_missing_members() -> None:
    document = {
        "name": "r",
        "stateVariables": [
            {"name": "a", "type": "int", "value": ""},
            {"name": "b", "type": "float", "value": ""},
            {"name": "c", "type": "bool", "value": ""},
            {"name": "d", "type": "string", "value": ""},
            {"name": "e", "type": "string", "value": "plain <text>"},
            {"name": "f", "type": "int", "value": -3},
            {"name": "g", "type": "float", "value": 2.5e-7},
            {"name": "h", "type": "bool", "value": True},
            {"name": "i", "type": "string", "value": "<>"},
            {"name": "j", "type": "int"},
        ],
        "connections": {"spp": [{"name": "c"}]},
        "interfaces": [
            {"name": "i", "type": "periodic",
             "primitiveCalls": [{"name": "p", "delay": 0, "priority": 0}, {"name": "p", "delay": 2.5, "priority": -1}]},
        ],
    }  # fmt: skip
    assert (
        printed(document)
        == """\
robot r {}

state a: int = 0

state b: float = 0.0

state c: bool = False

state d: string = ""

state e: string = "plain <text>"

state f: int = -3

state g: float = 2.5e-07

state h: bool = True

state i: string = "<>"

state j: int

connection c: serial {
    baud 9600
    threading single at 10 Hz
}

interface i() periodic {
    p()
    p() delay 2.5 ms priority -1
}
"""
    )


def test_adapters_standard_declared_and_made() -> None:
    document = {
        "name": "r",
        "domainAdapters": [{"name": "Pair", "ros": "pkg/Pair", "doc": "Two values.  \n",
                            "fields": [{"name": "a", "type": "int", "unit": "1", "ros": "a", "doc": "First."},
                                       {"name": "b", "type": "string"}]}],
        "domainInterfaces": [
            {"name": "set_velocity", "parameters": ["linear", "angular"], "calls": {"name": "drive", "arguments": []}},
            {"name": "set_pair", "adapter": "Pair", "parameters": ["a", "b"], "calls": {"name": "go"}},
            {"name": "set_mode", "parameters": ["mode", "level"], "calls": {"name": "go", "arguments": ["<mode>"]}},
        ],
        "domainOutputs": [
            {"name": "range", "returns": {"distance": ""}},
            {"name": "pair", "adapter": "Pair", "returns": {"a": "", "b": ""}},
            {"name": "set_mode", "returns": {"mode": ""}},
        ],
    }  # fmt: skip
    assert (
        printed(document)
        == """\
robot r {}

/// Two values.
adapter Pair ros "pkg/Pair" {
    /// First.
    a: int unit "1" ros "a"
    b: string
}

adapter SetModeMessage {
    mode: float
    level: float
}

adapter SetModeMessage2 {
    mode: float
}

input set_velocity: DifferentialSpeed -> drive()

input set_pair: Pair -> go()

input set_mode: SetModeMessage -> go(mode)

output range: Range {
    distance = 0.0
}

output pair: Pair {
    a = 0
    b = ""
}

output set_mode: SetModeMessage2 {
    mode = 0.0
}
"""
    )


CANONICAL = {
    "name": "rover",
    "author": "A. Uthor",
    "description": "Test.",
    "version": "2",
    "doc": "A rover.\nSecond line.",
    "stateVariables": [{"name": "hits", "type": "int", "value": "<0>", "doc": "Hits."}],
    "connections": {"spp": [{"name": "link", "baud": 57600, "singleThreading": {"freqHz": 12.5},
                             "startup": {"name": "go", "arguments": ["<0.5>"]},
                             "terminate": {"name": "go", "arguments": ["<-1.0>"]},
                             "keepalive": {"name": "poll", "interval": 1000, "arguments": []}, "doc": "Radio."}]},
    "primitives": [
        {"name": "move", "parameters": ["v"], "parameterTypes": ["int"], "connection": "link", "pack": ">Bh",
         "formatArgs": ["<137>", "<v>"]},
        {"name": "sense", "parameters": [], "parameterTypes": [], "connection": "link", "format": "S\n",
         "formatArgs": [], "regex": "^s,(\\d+)$", "postActions": ["hits = int(__out__[0])", "<hits = hits>"],
         "doc": "Read."},
    ],
    "interfaces": [
        {"name": "go", "type": "adhoc", "parameters": ["speed"], "parameterTypes": ["float"],
         "primitiveCalls": [{"name": "move", "arguments": ["<round(speed * -1000.0)>"], "delay": 100,
                             "priority": 0}]},
        {"name": "poll", "type": "periodic",
         "primitiveCalls": [{"name": "sense", "arguments": [], "delay": 0, "priority": 0}], "triggers": "bump"},
    ],
    "domainInterfaces": [{"name": "wheels", "adapter": "DifferentialSpeed", "parameters": ["linear", "angular"],
                          "calls": {"name": "go", "arguments": ["<linear>"]}}],
    "domainOutputs": [{"name": "bump", "adapter": "Range", "returns": {"distance": "<0.0 if hits > 0 else 1.0>"},
                       "doc": "Obstacle."}],
}  # fmt: skip


def test_canonical_form() -> None:
    assert (
        printed(CANONICAL)
        == r"""/// A rover.
/// Second line.
robot rover {
    author "A. Uthor"
    description "Test."
    version "2"
}

/// Hits.
state hits: int = 0

/// Radio.
connection link: serial {
    baud 57600
    threading single at 12.5 Hz
    startup go(0.5)
    terminate go(-1.0)
    keepalive poll() every 1000 ms
}

primitive move(v: int) on link pack ">Bh" (137, v)

/// Read.
primitive sense() on link format "S\n" () regex r"^s,(\d+)$" {
    hits = int(out[0])
    hits = hits
}

interface go(speed: float) {
    move(round(speed * -1000.0)) delay 100 ms
}

interface poll() periodic triggers bump {
    sense()
}

input wheels: DifferentialSpeed -> go(linear)

/// Obstacle.
output bump: Range {
    distance = 0.0 if hits > 0 else 1.0
}
"""
    )


ERRORS = [
    # (JSON text, code, line, column, message)
    ('{\n  "name": "x"\n  "author": "y"\n}', "E008", 3, 3, 'invalid JSON: expected `,` or `}`, found `"author"`'),
    ('{\n  "name": "x",\n}', "E008", 3, 1, "invalid JSON: expected a string, found `}`"),
    ('{\n  "name": "x\\q"\n}', "E008", 2, 13, "invalid JSON: unknown escape `\\q` in a string"),
    ('{\n  "name": "x\n}', "E008", 2, 11, "invalid JSON: unterminated string"),
    ('{"name": "a\tb"}', "E008", 1, 12, "invalid JSON: control character U+0009 in a string (write it as an escape)"),
    ("", "E008", 1, 1, "invalid JSON: expected a value, found the end of the file"),
    ("{'name': 1}", "E008", 1, 2, "invalid JSON: unexpected character `'`"),
    ("[1]", "E008", 1, 1, "a description is a JSON object, found an array"),
    ('{\n  "author": "x"\n}', "E008", 1, 1, "the description has no `name`"),
    ('{"name": "x",\n "primitive": []}', "E008", 2, 2, "unknown member `primitive` in the description"),
    ('{"name": 5}', "E008", 1, 10, "`name` must be a string, found a number"),
    ('{"name": "my robot"}', "E008", 1, 10,
     '`name` must be a name (a letter, then letters, digits or `_`), found "my robot"'),
    ('{"name": "x", "name": "y"}', "E008", 1, 15, "duplicate member `name`"),
    ('{"name": "x",\n "stateVariables": {}}', "E008", 2, 20, "`stateVariables` must be an array, found an object"),
    ('{"name": "x",\n "stateVariables": [{"name": "s", "value": 1}]}', "E008", 2, 21, "a state variable has no `type`"),
    ('{"name": "x",\n "stateVariables": [{"name": "s", "type": "int", "value": {}}]}', "E008", 2, 59,
     "expected an expression (a number, true/false, a string or an array), found an object"),
    ('{"name": "x",\n "stateVariables": [{"name": "s", "type": "int", "value": "<1 +>"}]}', "E001", 2, 64,
     "expected an expression, found the end of the expression"),
    ('{"name": "x",\n "stateVariables": [{"name": "s", "type": "int", "value": "<_x>"}]}', "E002", 2, 61,
     "names cannot start with `_`"),
    ('{"name": "x",\n "stateVariables": [{"name": "s", "type": "int", "value": 1e999}]}', "E004", 2, 59,
     "number too large for a float"),
    ('{"name": "x",\n "primitives": [{"name": "p", "postActions": ["s == 1"]}]}', "E008", 2, 47,
     "a post-action is written `state = expression`"),
    ('{"name": "x",\n "primitives": [{"name": "p", "parameters": ["a"], "parameterTypes": []}]}', "E008", 2, 70,
     "`parameterTypes` has 0 entries for 1 parameters"),
    ('{"name": "x",\n "primitives": [{"name": "p", "formatArgs": ["<1>"]}]}', "E008", 2, 45,
     "`formatArgs` without a `pack` or `format` to send them with"),
    ('{"name": "x",\n "interfaces": [{"name": "i", "type": "sometimes"}]}', "E008", 2, 39,
     'an interface\'s `type` is `adhoc` or `periodic`, not "sometimes"'),
    ('{"name": "x",\n "connections": {"usb": []}}', "E008", 2, 18, "unknown connection kind `usb`"),
    ('{"name": "x",\n "connections": {"spp": [{"name": "c", "keepalive": {"name": "k"}}]}}', "E008", 2, 53,
     "the `keepalive` hook has no `interval`"),
    ('{"name": "x",\n "domainOutputs": [{"name": "o"}]}', "E008", 2, 20, "a domain output has no `returns`"),
    ('{"name": "x",\n "links": [{"name": "l", "visuals": [{"size": [1]}]}]}', "E008", 2, 38,
     "a visual shape has no `shape`"),
    ('{"name": "x",\n "links": [{"name": "l", "inertial": {"mass": 1, "inertia": [1, 1, 1], "centre_": [0, 0, 0]}}]}',
     "E008", 2, 72, "unknown member `centre_` in `inertial`"),
    ('{"name": "x",\n "joints": [{"name": "j", "type": "fixed", "child": "b"}]}', "E008", 2, 13,
     "a joint has no `parent`"),
    ('{"name": "x",\n "joints": [{"name": "j", "type": "revolute", "parent": "a", "child": "b", "limit": [1]}]}',
     "E008", 2, 85, "a joint's limit is `[low, high]`"),
    (('{"name": "x",\n "transmissions": [{"name": "t", "joint": "j", "commands": [{"quantity": "position", '
     '"parameter": "p", "toDevice": "<position>", "toJoint": "<raw>"}]}]}'), "E008", 2, 61,
     "a command names one `primitive` or one `interface`"),
    (('{"name": "x",\n "transmissions": [{"name": "t", "joint": "j", "measures": [{"quantity": "position", '
     '"state": "s", "toDevice": "<position>"}]}]}'), "E008", 2, 61, "a measure has no `toJoint`"),
    (('{"name": "x",\n "transmissions": [{"name": "t", "joint": "j", "measures": [{"quantity": "position", '
     '"state": "s", "toDevice": "<position +>", "toJoint": "<raw>"}]}]}'), "E001", 2, 124,
     "expected an expression, found the end of the expression"),
    ("[" * (MAX_DEPTH + 1) + "]" * (MAX_DEPTH + 1), "E005", 1, MAX_DEPTH + 1,
     f"JSON is nested too deeply (the limit is {MAX_DEPTH} levels)"),
    ("[" + "1," * MAX_VALUES + "1]", "E005", 1, 2 * MAX_VALUES + 1,
     f"JSON has too many values (the limit is {MAX_VALUES})"),
]  # fmt: skip


@pytest.mark.parametrize(("text", "code", "line", "column", "message"), ERRORS)
def test_errors(text: str, code: str, line: int, column: int, message: str) -> None:
    _, diagnostics = imported(text)
    (d,) = diagnostics.items
    position = SourceFile("t.json", text).position(d.span.start)
    assert (d.code, position.line + 1, position.column + 1, d.message) == (code, line, column, message)


def test_the_body_checked_from_json_points_into_the_json(tmp_path: Path) -> None:
    """The checker's diagnostics about a body read from JSON are at the JSON's lines: a zero axis,
    two parents, a command naming a primitive as an interface."""
    document = json.loads(compile_json(ROOT / "tests" / "golden" / "json" / "body.rdis"))
    document["joints"][0]["axis"] = [0, 0, 0]
    document["joints"][1]["child"] = "upper"
    document["transmissions"][1]["commands"][0]["primitive"] = document["transmissions"][1]["commands"][0].pop(
        "interface")
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "base.stl").write_bytes(b"")  # the mesh body.rdis names, beside the copy
    path = tmp_path / "body.json"
    text = json.dumps(document, indent=1)
    path.write_text(text, encoding="utf-8")
    compilation = compile_path(str(path))
    found = [(d.code, text[d.span.start:d.span.end], d.message) for d in compilation.diagnostics.items]
    assert found == [
        ("E008", '"slide"', "`slide` is an interface"),
        ("E603", "[\n    0,\n    0,\n    0\n   ]", "an axis must not be zero"),
        ("E601", "upper", "link `upper` is the child of two joints"),
        ("E601", "camera", "link `camera` is not joined to the tree of `base`"),
    ]


def compile_json(path: Path) -> str:
    from rdisc.emit.canonical import to_json

    compilation = compile_path(str(path))
    assert compilation.model is not None
    return to_json(compilation.model)


def test_unknown_member_suggests_the_closest() -> None:
    _, diagnostics = imported('{"name": "x", "primitive": []}')
    assert diagnostics.items[0].help == "did you mean `primitives`?"


def test_broken_element_is_left_out_without_follow_on_errors(tmp_path: Path) -> None:
    """As with a syntax error in source: the broken primitive is gone, and the
    interface calling it is not reported again for an unknown primitive."""
    document = json.loads((DATA / "thesis_create.json").read_text(encoding="utf-8"))
    document["primitives"][3]["postActions"] = ["bumperStates = __out__[0"]
    document["interfaces"][1]["primitiveCalls"][0]["arguments"] = [
        "<round(velocity * 1000)>",
        "<round(radius * 1000)>",
    ]
    path = tmp_path / "create.json"
    path.write_text(json.dumps(document, indent=2), encoding="utf-8")
    compilation = compile_path(str(path))
    assert [(d.code, d.message) for d in compilation.diagnostics.items if d.severity == 1] == [
        ("E001", "expected a closing `]`, found the end of the expression")
    ]


json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False, allow_infinity=False) | st.text(),
    lambda children: st.lists(children, max_size=4) | st.dictionaries(
        st.sampled_from(["name", "type", "value", "parameters", "primitives", "interfaces", "stateVariables",
                         "connections", "spp", "formatArgs", "pack", "postActions", "returns", "calls", "x",
                         "links", "joints", "transmissions", "visuals", "shape", "size", "inertial", "mass",
                         "parent", "child", "limit", "commands", "measures", "quantity", "state", "toDevice"]),
        children, max_size=5),
    max_leaves=30,
)  # fmt: skip


@settings(max_examples=300, deadline=None)
@given(json_values)
def test_any_json_is_a_module_or_diagnostics(value: object) -> None:
    module, diagnostics = imported(json.dumps(value))
    assert module is not None or diagnostics.has_errors()


@settings(max_examples=300, deadline=None)
@given(st.text())
def test_any_text_is_a_module_or_diagnostics(text: str) -> None:
    module, diagnostics = imported(text)
    assert module is not None or diagnostics.has_errors()


def test_deep_expression_is_refused() -> None:
    text = (
        '{"name": "x",\n "stateVariables": [{"name": "s", "type": "int", "value": "<' + "-" * 300 + '1>"}]}'
    )
    module, diagnostics = imported(text)
    (d,) = diagnostics.items
    assert d.code == "E005" and d.message.startswith("expression is nested too deeply")
    assert SourceFile("t.json", text).position(d.span.start).line == 1 and text[d.span.start] == "-"
    assert module is not None and module.damaged == (ast.Damaged("state", ast.Ident("s")),)


def test_an_input_keeps_the_order_of_its_parameters() -> None:
    """Appendix B lists `angular, linear`: the standard adapter is copied in that order, with its
    units and ROS paths, so that the order comes back from `rdisc build`."""
    document = {"name": "r", "domainInterfaces": [
        {"name": "set_velocity", "parameters": ["angular", "linear"], "calls": {"name": "drive", "arguments": []}}]}
    assert printed(document) == """\
robot r {}

/// DifferentialSpeed, with its fields in the order of `set_velocity`.
adapter SetVelocityMessage ros "geometry_msgs/Twist" {
    /// Rate of turn about the vertical axis; positive is counter-clockwise.
    angular: float unit "rad/s" ros "angular.z"
    /// Forward speed of the robot's centre; negative drives backwards.
    linear: float unit "m/s" ros "linear.x"
}

input set_velocity: SetVelocityMessage -> drive()
"""


def test_appendix_b_checks_and_its_build_keeps_what_it_says(tmp_path: Path) -> None:
    """Appendix B as the thesis ran it: no error, the truncations shown, and building it, importing
    the build and building again gives the same JSON, with `set_velocity`'s parameters in their order."""
    from rdisc.emit.canonical import to_json

    compilation = compile_path(str(DATA / "thesis_create.json"))
    assert compilation.model is not None
    assert [d.code for d in compilation.diagnostics.items] == ["W403", "W403", "W402"]
    built = to_json(compilation.model)
    (tmp_path / "built.json").write_text(built, encoding="utf-8")
    again = compile_path(str(tmp_path / "built.json"))
    assert again.model is not None and not again.diagnostics.has_errors()
    assert to_json(again.model) == built
    (velocity,) = json.loads(built)["domainInterfaces"]
    assert velocity["parameters"] == ["angular", "linear"]


def test_doc_comments_of_constants_tables_and_enums_survive_build_and_import(tmp_path: Path) -> None:
    """Their JSON values are plain, so their doc comments travel beside them, by name."""
    from rdisc.emit.canonical import to_json

    source = tmp_path / "d.rdis"
    source.write_text("""\
robot r { author "tests" }
connection port: serial { baud 115200 }
/// The servo IDs.
const IDS = [1, 2]
/// Baud rate codes.
const BAUD_CODE = { 9600: 1, 19200: 2 }
/// The commands.
enum Cmd { a = 1, b = 2 }
primitive q() on port pack "BBB" (Cmd.a, IDS[0], BAUD_CODE[9600])
""", encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    built = json.loads(to_json(compilation.model))
    assert (built["constantDocs"], built["enumDocs"]) == (
        {"IDS": "The servo IDs.", "BAUD_CODE": "Baud rate codes."}, {"Cmd": "The commands."})
    module, diagnostics = imported(to_json(compilation.model))
    assert module is not None and not diagnostics.items
    text = print_module(module)
    assert "/// The servo IDs.\nconst IDS = [1, 2]\n" in text
    assert "/// Baud rate codes.\nconst BAUD_CODE = {" in text
    assert "/// The commands.\nenum Cmd {" in text
    built["enumDocs"]["Nothing"] = "A doc of no enum."
    module, diagnostics = imported(json.dumps(built))
    assert [(d.code, d.message) for d in diagnostics.items] == [
        ("E008", "`enumDocs` names `Nothing`, which the description does not declare")]
