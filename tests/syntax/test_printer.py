"""The printer: canonical text, fewest parentheses, and parse(print(m)) == m."""

from __future__ import annotations

import math
import string
from pathlib import Path

import pytest
from conftest import fuzz_examples
from hypothesis import given, settings
from hypothesis import strategies as st

from rdisc.diagnostics import Diagnostics
from rdisc.semantics.resolve import KEYWORDS
from rdisc.syntax import ast
from rdisc.syntax.parse import DECL_KEYWORDS, parse, parse_expression
from rdisc.syntax.printer import print_expr, print_module

ROOT = Path(__file__).resolve().parents[2]


def parsed(text: str, path: str = "t.rdis") -> ast.Module:
    diagnostics = Diagnostics()
    module = parse(path, text, diagnostics)
    assert not diagnostics.items, diagnostics.items
    return module


def expr(text: str) -> ast.Expr:
    diagnostics = Diagnostics()
    result = parse_expression("t.rdis", text, 0, diagnostics)
    assert result is not None and not diagnostics.items, diagnostics.items
    return result


SOURCE = r"""
import   "more.rdis"
robot   koala { author "K-Team"   version "1.0\n\"beta\"" }
/// Metres per pulse.
state  mpp : float = 4.5e-5
state count: int
///   Serial line.
///
///   Second paragraph.
connection rs232 : serial { threading single at 10 Hz baud 38400
   startup init() keepalive ping(1, "x") every 1 s terminate stop() }
primitive set_speed(left: int, right: int) on rs232 format "D,{},{}\n" (left, right) regex r"^d\s*$"
primitive read() on rs232 format "E\n" () regex "^e,(-?\\d+),(-?\\d+)\t$" { a = int(out[0]) b = int(out[1]) }
primitive ping(n: int, s: string) { } on rs232 pack "B" (n)
primitive one() on rs232 pack ">h" (-1) unpack ">h" { count = out[0] }
primitive a_primitive_with_a_long_name(first_parameter: int, second_parameter: int) on rs232 pack ">Bhh" (137, first_parameter, second_parameter) unpack ">hh" { x = out[0] y = out[1] }
interface drive(velocity: float   unit   "m/s", radius: float in -2..2 unit "m" = 0.0) adhoc triggers odometry {
  set_speed(round(velocity * 1000), round(radius * 1000)) delay 100 ms priority 2 delay 5 s
  set_speed(0, 0)
}
interface nothing() periodic { }
adapter Wheel ros "pkg/Wheel" {
  /// Speed of the wheel.
  speed: float unit "m/s" ros "speed"
  name: string
}
adapter Empty { }
input set_velocity: DifferentialSpeed -> drive(clamp(linear, -0.5, 0.5), 0.0 if linear == 0 and angular == 0 else linear / angular)
output odometry: Odometry { x = mpp * count  y = 0.0 }
output none: Empty {}
"""

EXPECTED = r"""import "more.rdis"

robot koala {
    author "K-Team"
    version "1.0\n\"beta\""
}

/// Metres per pulse.
state mpp: float = 4.5e-05

state count: int

/// Serial line.
///
///   Second paragraph.
connection rs232: serial {
    threading single at 10 Hz
    baud 38400
    startup init()
    keepalive ping(1, "x") every 1 s
    terminate stop()
}

primitive set_speed(left: int, right: int) on rs232 format "D,{},{}\n" (left, right) regex r"^d\s*$"

primitive read() on rs232 format "E\n" () regex "^e,(-?\\d+),(-?\\d+)\t$" {
    a = int(out[0])
    b = int(out[1])
}

primitive ping(n: int, s: string) {} on rs232 pack "B" (n)

primitive one() on rs232 pack ">h" (-1) unpack ">h" { count = out[0] }

primitive a_primitive_with_a_long_name(first_parameter: int, second_parameter: int)
    on rs232
    pack ">Bhh" (137, first_parameter, second_parameter)
    unpack ">hh" {
        x = out[0]
        y = out[1]
    }

interface drive(velocity: float unit "m/s", radius: float in -2..2 unit "m" = 0.0) adhoc triggers odometry {
    set_speed(round(velocity * 1000), round(radius * 1000)) delay 100 ms delay 5 s priority 2
    set_speed(0, 0)
}

interface nothing() periodic {}

adapter Wheel ros "pkg/Wheel" {
    /// Speed of the wheel.
    speed: float unit "m/s" ros "speed"
    name: string
}

adapter Empty {}

input set_velocity: DifferentialSpeed -> drive(
    clamp(linear, -0.5, 0.5),
    0.0 if linear == 0 and angular == 0 else linear / angular,
)

output odometry: Odometry {
    x = mpp * count
    y = 0.0
}

output none: Empty {}
"""


def test_canonical_text() -> None:
    module = parsed(SOURCE)
    assert print_module(module) == EXPECTED
    assert parsed(EXPECTED) == module


BODY = """
link base { visual cylinder(0.17, 0.09) at [0, 0, 0.045]   collision box(0.3, 0.3, 0.09) rpy [0, 0, (1.5)]
  mass 3.6 centre [0, 0, 0.03] inertia [0.02, 0.02, 0.035, 0, 0, 0.001] visual mesh("m.stl", [1, 1, 2]) }
link arm {}
/// The shoulder.
joint lift: revolute base -> arm { limit -(1.5)..1.5 velocity 2 effort 1 axis [0, 0, 1] damping 0.1 friction 0 }
transmission lifter: lift {
  command position to servo.goal { raw = round(position * 195.3) + 512   position = (raw - 512) / 195.3 }
  measure position from present[ID - 1] { raw = round(position * 195.3) + 512 position = (raw - 512) / 195.3 }
  command effort to torque.limit[0] {}
}
"""

BODY_EXPECTED = """link base {
    visual cylinder(0.17, 0.09) at [0, 0, 0.045]
    collision box(0.3, 0.3, 0.09) rpy [0, 0, 1.5]
    mass 3.6
    centre [0, 0, 0.03]
    inertia [0.02, 0.02, 0.035, 0, 0, 0.001]
    visual mesh("m.stl", [1, 1, 2])
}

link arm {}

/// The shoulder.
joint lift: revolute base -> arm {
    limit -1.5..1.5
    velocity 2
    effort 1
    axis [0, 0, 1]
    damping 0.1
    friction 0
}

transmission lifter: lift {
    command position to servo.goal {
        raw = round(position * 195.3) + 512
        position = (raw - 512) / 195.3
    }
    measure position from present[ID - 1] {
        raw = round(position * 195.3) + 512
        position = (raw - 512) / 195.3
    }
    command effort to torque.limit[0] {}
}
"""


def test_the_body_prints_back() -> None:
    """Links, joints and transmissions: every clause in the order written, one a line."""
    module = parsed(BODY)
    assert print_module(module) == BODY_EXPECTED
    assert parsed(BODY_EXPECTED) == module


def test_an_output_s_frame_prints_back() -> None:
    """`frame LINK` after the adapter, before the fields."""
    text = "output detect_bump: Range frame bumper {\n    distance = 0.0\n}\n"
    module = parsed(text)
    assert module.decls[0].frame == ast.Ident("bumper")  # type: ignore[union-attr]
    assert print_module(module) == text


def test_empty_module() -> None:
    assert print_module(ast.Module("t.rdis", ())) == ""


@pytest.mark.parametrize(
    "path",
    [ROOT / "stdlib" / "adapters.rdis", *sorted((ROOT / "examples").glob("*.rdis"))],
    ids=lambda p: p.name,
)
def test_shipped_sources_round_trip(path: Path) -> None:
    module = parsed(path.read_text(encoding="utf-8"), str(path))
    text = print_module(module)
    assert parsed(text, str(path)) == module
    assert print_module(parsed(text, str(path))) == text  # printing is a fixed point


@pytest.mark.parametrize(
    ("source", "printed"),
    [
        ("(a + b) * c", "(a + b) * c"),
        ("a + (b * c)", "a + b * c"),
        ("a - (b - c)", "a - (b - c)"),
        ("(a - b) - c", "a - b - c"),
        ("-2 ** 2", "-2 ** 2"),
        ("(-2) ** 2", "(-2) ** 2"),
        ("2 ** -1", "2 ** -1"),
        ("(2 ** 3) ** 2", "(2 ** 3) ** 2"),
        ("2 ** (3 ** 2)", "2 ** 3 ** 2"),
        ("-(a + b)", "-(a + b)"),
        ("- -a", "--a"),
        ("~(a & b)", "~(a & b)"),
        ("(a < b) == c", "(a < b) == c"),
        ("a < (b == c)", "a < (b == c)"),
        ("not (a == b)", "not a == b"),
        ("(not a) == b", "(not a) == b"),
        ("not (a and b)", "not (a and b)"),
        ("(a or b) and c", "(a or b) and c"),
        ("a or (b and c)", "a or b and c"),
        ("(a & 3) == 0", "(a & 3) == 0"),
        ("a | (b ^ c)", "a | b ^ c"),
        ("(a | b) ^ c", "(a | b) ^ c"),
        ("(a << 2) + 1", "(a << 2) + 1"),
        ("a << (2 + 1)", "a << 2 + 1"),
        ("(a if b else c) if d else e", "(a if b else c) if d else e"),
        ("a if (b if c else d) else e", "a if (b if c else d) else e"),
        ("a if b else (c if d else e)", "a if b else c if d else e"),
        ("(a if b else c) + 1", "(a if b else c) + 1"),
        ("f(a if b else c, (d))", "f(a if b else c, d)"),
        ("out[(1 + 2)]", "out[1 + 2]"),
        ("0x1F + 1_000", "31 + 1000"),
        ("1.0 + .5 + 1e3 + 1e-5", "1.0 + 0.5 + 1000.0 + 1e-05"),
        ("True or False", "True or False"),
        ('"tab\\there" + r"\\d"', '"tab\\there" + "\\\\d"'),
    ],
)
def test_fewest_parentheses(source: str, printed: str) -> None:
    assert print_expr(expr(source)) == printed
    assert expr(printed) == expr(source)


@pytest.mark.parametrize(
    ("node", "printed"),
    [
        (ast.FloatLit(1e16), "1e+16"),
        (ast.FloatLit(5e-324), "5e-324"),
        (ast.IntLit(-3), "-3"),
        (ast.BinOp("**", ast.IntLit(-3), ast.IntLit(2)), "(-3) ** 2"),
        (ast.FloatLit(-0.0), "-0.0"),
        (ast.FloatLit(math.inf), 'float("inf")'),
        (ast.FloatLit(math.nan), 'float("nan")'),
        (
            ast.StrLit('a"\\\n\r\t\0\x07\x85\u2028\U000e0001é'),
            '"a\\"\\\\\\n\\r\\t\\0\\x07\\x85\\u2028\U000e0001é"',
        ),
    ],
)
def test_literals_outside_what_the_parser_makes(node: ast.Expr, printed: str) -> None:
    """Constants a checker or an importer may build still print as valid RDIS."""
    assert print_expr(node) == printed


# ---- property: print, then parse, gives the same tree --------------------------------------

_RESERVED = KEYWORDS | set(DECL_KEYWORDS) | {
    "r", "on", "pack", "format", "unpack", "regex", "periodic", "adhoc", "triggers", "baud", "threading",
    "at", "Hz", "startup", "terminate", "keepalive", "every", "ms", "s", "unit", "ros",
    "visual", "collision", "mass", "centre", "inertia", "rpy", "axis", "limit", "velocity", "effort", "damping",
    "friction", "command", "measure", "to", "from",
}  # fmt: skip

# A letter, then up to six letters, digits or underscores: the strings of [A-Za-z][A-Za-z0-9_]{0,6}, drawn
# as two parts where `st.from_regex` cost a millisecond a name (a third of the module test's CPU).
names = st.builds(
    lambda first, rest: first + rest,
    st.sampled_from(string.ascii_letters),
    st.text(string.ascii_letters + string.digits + "_", max_size=6),
).filter(lambda n: n not in _RESERVED)

leaves = st.one_of(
    st.integers(0, 2**64 - 1).map(ast.IntLit),
    st.floats(min_value=0.0, allow_nan=False, allow_infinity=False).map(lambda x: ast.FloatLit(abs(x))),
    st.text().map(ast.StrLit),
    st.booleans().map(ast.BoolLit),
    names.map(ast.Ref),
)

BINARY_OPS = ["or", "and", "==", "!=", "<", "<=", ">", ">=", "|", "^", "&", "<<", ">>", "+", "-", "*", "/", "//",
              "%", "**"]  # fmt: skip


def _compound(children: st.SearchStrategy[ast.Expr]) -> st.SearchStrategy[ast.Expr]:
    return st.one_of(
        st.builds(ast.Unary, st.sampled_from(["-", "+", "~", "not"]), children),
        st.builds(ast.BinOp, st.sampled_from(BINARY_OPS), children, children),
        st.builds(ast.Conditional, children, children, children),
        st.builds(ast.CallExpr, names.map(ast.Ident), st.lists(children, max_size=3).map(tuple)),
        st.builds(ast.Index, names.map(ast.Ref), children),
    )


expressions = st.recursive(leaves, _compound, max_leaves=25)


@settings(max_examples=fuzz_examples(200), deadline=None)
@given(expressions)
def test_print_then_parse_gives_the_same_expression(e: ast.Expr) -> None:
    diagnostics = Diagnostics()
    assert parse_expression("t.rdis", print_expr(e), 0, diagnostics) == e, diagnostics.items


docs = st.none() | st.lists(
    st.text(st.characters(blacklist_characters="\n\r", blacklist_categories=["Cs"]), max_size=20),
    min_size=1,
    max_size=3,
).map(lambda lines: "\n".join(line.rstrip() for line in lines).strip())
ids = names.map(ast.Ident)
params = st.lists(st.builds(ast.Param, ids, ids), max_size=3).map(tuple)
args = st.lists(expressions, max_size=3).map(tuple)
calls = st.builds(ast.Call, ids, args)
durations = st.builds(ast.Duration, expressions, st.sampled_from(["ms", "s"]))
assigns = st.builds(ast.Assign, ids, expressions)
body_stmts = st.recursive(
    st.builds(ast.CallStmt, calls, st.lists(durations, max_size=2).map(tuple),
              st.lists(expressions, max_size=2).map(tuple), conditions=st.lists(expressions, max_size=1).map(tuple)),
    lambda inner: st.builds(ast.ForStmt, ids, expressions, st.none() | expressions,
                            st.lists(inner, min_size=1, max_size=2).map(tuple)),
    max_leaves=4,
)  # a loop's body: calls and loops
strings = st.text(st.characters(blacklist_categories=["Cs"]), max_size=12)

declarations = st.one_of(
    st.builds(ast.StateDecl, ids, ids, st.none() | expressions, doc=docs),
    st.builds(
        ast.ConnectionDecl, ids, ids,
        st.lists(st.one_of(
            st.builds(ast.Baud, expressions),
            st.builds(ast.Threading, ids, expressions),
            st.builds(ast.Hook, st.sampled_from(["startup", "terminate"]), calls, st.none()),
            st.builds(ast.Hook, st.just("keepalive"), calls, durations),
        ), max_size=4).map(tuple),
        doc=docs,
    ),
    st.builds(
        ast.PrimitiveDecl, ids, params,
        st.lists(st.one_of(
            st.builds(ast.On, ids),
            st.builds(ast.Encoding, st.sampled_from(["pack", "format"]), strings.map(ast.StrLit), args),
            st.builds(ast.Decoding, st.sampled_from(["unpack", "regex"]), strings.map(ast.StrLit)),
            st.builds(ast.Actions, st.lists(assigns, max_size=3).map(tuple)),
        ), max_size=5).map(tuple),
        doc=docs,
    ),
    st.builds(
        ast.InterfaceDecl, ids, params,
        st.lists(st.one_of(st.builds(ast.Kind, st.sampled_from(["periodic", "adhoc"])),
                           st.builds(ast.Triggers, st.lists(ids, min_size=1, max_size=3).map(tuple))),
                 max_size=2).map(tuple),
        st.lists(body_stmts, max_size=3).map(tuple),
        doc=docs,
    ),
    st.builds(
        ast.AdapterDecl, ids, st.none() | strings.map(ast.StrLit),
        st.lists(st.builds(ast.FieldDecl, ids, ids, st.none() | strings, st.none() | strings.map(ast.StrLit),
                           doc=docs),
                 max_size=3).map(tuple),
        doc=docs,
    ),
    st.builds(ast.InputDecl, ids, ids, calls, doc=docs),
    st.builds(ast.OutputDecl, ids, ids, st.lists(assigns, max_size=3).map(tuple), doc=docs, frame=st.none() | ids),
    st.builds(ast.ImportDecl, strings, doc=docs),
    st.builds(
        ast.LinkDecl, ids,
        st.lists(st.one_of(
            st.builds(ast.ShapeUse, st.sampled_from(["visual", "collision"]), st.builds(ast.Shape, ids, args),
                      st.none() | expressions, st.none() | expressions),
            st.builds(ast.BodyValue, st.sampled_from(["mass", "centre", "inertia"]), expressions),
        ), max_size=4).map(tuple),
        doc=docs,
    ),
    st.builds(
        ast.JointDecl, ids, ids, ids, ids,
        st.lists(st.one_of(
            st.builds(ast.BodyValue, st.sampled_from(["at", "rpy", "axis", "velocity", "effort", "damping",
                                                      "friction"]), expressions),
            st.builds(ast.JointLimit, expressions, expressions),
        ), max_size=4).map(tuple),
        doc=docs,
    ),
    st.builds(
        ast.TransmissionDecl, ids, ids,
        st.lists(st.one_of(
            st.builds(ast.Binding, st.just("command"), ids, ids, ids, st.none() | expressions,
                      st.lists(assigns, max_size=2).map(tuple)),
            st.builds(ast.Binding, st.just("measure"), ids, ids, st.none(), st.none() | expressions,
                      st.lists(assigns, max_size=2).map(tuple)),
        ), max_size=3).map(tuple),
        doc=docs,
    ),
    st.builds(
        ast.RobotDecl, ids,
        st.lists(st.builds(ast.RobotAttr, st.sampled_from(["author", "description", "version"]), strings),
                 max_size=3).map(tuple),
        doc=docs,
    ),
)  # fmt: skip


@settings(max_examples=fuzz_examples(100), deadline=None)
@given(st.lists(declarations, max_size=6).map(lambda decls: ast.Module("t.rdis", tuple(decls))))
def test_print_then_parse_gives_the_same_module(module: ast.Module) -> None:
    diagnostics = Diagnostics()
    text = print_module(module)
    assert parse("t.rdis", text, diagnostics) == module, (text, diagnostics.items)
