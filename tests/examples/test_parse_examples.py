"""The shipped RDIS sources parse cleanly: the standard adapters and every example.

Parsing only; checking the examples against the model's rules belongs to the
checker's tests. Two semantic facts are pinned here because the examples exist to
show them: the standard adapters carry docs, units and ROS paths, and the Create's
`set_velocity` reproduces the "Expected" column of thesis Table 4.3.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import pytest

from rdisc.diagnostics import Diagnostics
from rdisc.semantics.operators import BINARY, FUNCTIONS, UNARY
from rdisc.syntax import ast
from rdisc.syntax.parse import parse

ROOT = Path(__file__).resolve().parents[2]
STDLIB = ROOT / "stdlib" / "adapters.rdis"
EXAMPLES = ROOT / "examples"

# Declarations per kind, by file (paths relative to the repository root).
EXPECTED_COUNTS: dict[str, dict[str, int]] = {
    "stdlib/adapters.rdis": {"AdapterDecl": 8},
    "examples/create.rdis": {
        "RobotDecl": 1,
        "StateDecl": 1,
        "ConnectionDecl": 1,
        "PrimitiveDecl": 4,
        "InterfaceDecl": 4,
        "InputDecl": 1,
        "OutputDecl": 1,
    },
    "examples/koala.rdis": {
        "RobotDecl": 1,
        "StateDecl": 13,
        "ConnectionDecl": 1,
        "PrimitiveDecl": 5,
        "InterfaceDecl": 5,
        "InputDecl": 1,
        "OutputDecl": 2,
    },
}

SOURCES = [STDLIB, *sorted(EXAMPLES.glob("*.rdis"))]


def _parse(path: Path) -> ast.Module:
    diagnostics = Diagnostics()
    module = parse(str(path), path.read_text(encoding="utf-8"), diagnostics)
    found = [(d.code, d.message) for d in diagnostics.sorted()]
    assert found == [], f"{path.relative_to(ROOT)}: {found}"
    return module


def _decl(module: ast.Module, kind: type, name: str):
    return next(d for d in module.decls if isinstance(d, kind) and d.name.text == name)


@pytest.mark.parametrize("path", SOURCES, ids=lambda p: str(p.relative_to(ROOT)))
def test_parses_without_diagnostics(path: Path) -> None:
    module = _parse(path)
    rel = str(path.relative_to(ROOT))
    assert rel in EXPECTED_COUNTS, f"add the declaration counts of {rel} to EXPECTED_COUNTS"
    assert Counter(type(d).__name__ for d in module.decls) == Counter(EXPECTED_COUNTS[rel])


def test_every_expected_file_exists() -> None:
    for rel in EXPECTED_COUNTS:
        assert (ROOT / rel).is_file(), rel


# ---- the standard adapters ---------------------------------------------------------

# adapter: (ROS message, {field: (type, unit, ROS path)})
STANDARD_ADAPTERS = {
    "DifferentialSpeed": (
        "geometry_msgs/Twist",
        {"linear": ("float", "m/s", "linear.x"), "angular": ("float", "rad/s", "angular.z")},
    ),
    "Range": ("sensor_msgs/Range", {"distance": ("float", "m", "range")}),
    "Contact": ("std_msgs/Bool", {"contact": ("bool", None, "data")}),
    "Battery": (
        "sensor_msgs/BatteryState",
        {
            "voltage": ("float", "V", "voltage"),
            "current": ("float", "A", "current"),
            "charge": ("float", "Ah", "charge"),
            "capacity": ("float", "Ah", "capacity"),
            "percentage": ("float", "1", "percentage"),
        },
    ),
    "Odometry": (
        "nav_msgs/Odometry",
        {
            "x": ("float", "m", "pose.pose.position.x"),
            "y": ("float", "m", "pose.pose.position.y"),
            "theta": ("float", "rad", "pose.pose.orientation:yaw"),
            "linear": ("float", "m/s", "twist.twist.linear.x"),
            "angular": ("float", "rad/s", "twist.twist.angular.z"),
        },
    ),
    "Pose2D": (
        "geometry_msgs/Pose2D",
        {"x": ("float", "m", "x"), "y": ("float", "m", "y"), "theta": ("float", "rad", "theta")},
    ),
    "JointPosition": (
        "sensor_msgs/JointState",
        {"name": ("string", None, "name[0]"), "position": ("float", "rad", "position[0]")},
    ),
    "Temperature": (
        "sensor_msgs/Temperature",
        {"temperature": ("float", "degC", "temperature"), "variance": ("float", "degC^2", "variance")},
    ),
}


def test_standard_adapters() -> None:
    module = _parse(STDLIB)
    adapters = {d.name.text: d for d in module.decls if isinstance(d, ast.AdapterDecl)}
    assert set(adapters) == set(STANDARD_ADAPTERS)
    for name, (message, fields) in STANDARD_ADAPTERS.items():
        adapter = adapters[name]
        assert adapter.ros == message, name
        got = {f.name.text: (f.type.text, f.unit, f.ros) for f in adapter.fields}
        assert got == fields, name


def test_standard_adapters_are_documented() -> None:
    module = _parse(STDLIB)
    for adapter in module.decls:
        assert isinstance(adapter, ast.AdapterDecl), "the stdlib declares adapters only"
        assert adapter.doc, f"adapter {adapter.name.text} has no /// doc comment"
        for f in adapter.fields:
            assert f.doc, f"field {adapter.name.text}.{f.name.text} has no /// doc comment"
            if f.type.text in ("int", "float"):
                assert f.unit, f"numeric field {adapter.name.text}.{f.name.text} has no unit"
    odometry = _decl(module, ast.AdapterDecl, "Odometry")
    assert ":yaw" in odometry.doc
    assert "Celsius" in _decl(module, ast.AdapterDecl, "Temperature").doc


# ---- the Create's velocity mapping (thesis Table 4.3) ----------------------------------


def _evaluate(expr: ast.Expr, env: dict[str, object]) -> object:
    """A reference evaluator for the expressions of these tests, over the AST."""
    match expr:
        case ast.IntLit() | ast.FloatLit() | ast.StrLit() | ast.BoolLit():
            return expr.value
        case ast.Ref():
            return env[expr.name]
        case ast.Unary():
            return UNARY[expr.op](_evaluate(expr.operand, env))
        case ast.BinOp(op="and"):
            return _evaluate(expr.left, env) and _evaluate(expr.right, env)
        case ast.BinOp(op="or"):
            return _evaluate(expr.left, env) or _evaluate(expr.right, env)
        case ast.BinOp():
            return BINARY[expr.op](_evaluate(expr.left, env), _evaluate(expr.right, env))
        case ast.Conditional():
            return _evaluate(expr.then if _evaluate(expr.cond, env) else expr.orelse, env)
        case ast.CallExpr():
            return FUNCTIONS[expr.func.text](*(_evaluate(a, env) for a in expr.args))
    raise AssertionError(f"not expected in this test: {expr!r}")


def _apply(exprs: tuple[ast.Expr, ...], params: tuple[ast.Param, ...], args: list[object]) -> list[object]:
    """The values of `exprs` inside a declaration called with `args`."""
    env = {p.name.text: a for p, a in zip(params, args, strict=True)}
    return [_evaluate(e, env) for e in exprs]


TABLE_4_3 = [
    # (linear m/s, angular rad/s) -> (opcode, velocity mm/s, radius mm), "Expected" column
    ((-0.2, -0.4), (137, -200, 500)),
    ((0.0, 0.0), (137, 0, 0)),
    ((0.0, 0.2), (137, 0, -1)),
    ((0.0, -0.2), (137, 0, 1)),
    ((0.2, 0.0), (137, 200, 32767)),
    ((-0.2, 0.0), (137, -200, 32767)),
]


@pytest.mark.parametrize(("twist", "expected"), TABLE_4_3, ids=[str(t) for t, _ in TABLE_4_3])
def test_create_set_velocity_matches_table_4_3(twist, expected) -> None:
    module = _parse(EXAMPLES / "create.rdis")
    adapter = _decl(_parse(STDLIB), ast.AdapterDecl, "DifferentialSpeed")
    set_velocity = _decl(module, ast.InputDecl, "set_velocity")
    drive_iface = _decl(module, ast.InterfaceDecl, "drive")
    drive_prim = _decl(module, ast.PrimitiveDecl, "drive")

    fields = dict(zip((f.name.text for f in adapter.fields), twist, strict=True))
    iface_args = [_evaluate(a, fields) for a in set_velocity.call.args]
    (stmt,) = drive_iface.body
    prim_args = _apply(stmt.call.args, drive_iface.params, iface_args)
    assert all(isinstance(a, int) for a in prim_args)
    (encoding,) = [c for c in drive_prim.clauses if isinstance(c, ast.Encoding)]
    packed = _apply(encoding.args, drive_prim.params, prim_args)
    assert tuple(packed) == expected


@pytest.mark.parametrize(("linear", "angular"), [(0.9, 0.0), (-3.0, 0.5), (1.0, 0.1), (0.1, -0.01)])
def test_create_set_velocity_respects_open_interface_limits(linear, angular) -> None:
    module = _parse(EXAMPLES / "create.rdis")
    args = _decl(module, ast.InputDecl, "set_velocity").call.args
    velocity, radius = (_evaluate(a, {"linear": linear, "angular": angular}) for a in args)
    assert -0.5 <= velocity <= 0.5
    assert radius == 32.767 or -2.0 <= radius <= 2.0
