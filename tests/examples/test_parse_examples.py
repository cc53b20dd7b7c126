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
from rdisc.syntax import ast
from rdisc.syntax.parse import parse
from rdisc.syntax.printer import print_type

ROOT = Path(__file__).resolve().parents[2]
STDLIB = ROOT / "stdlib" / "adapters.rdis"
EXAMPLES = ROOT / "examples"

# Declarations per kind, by file (paths relative to the repository root).
EXPECTED_COUNTS: dict[str, dict[str, int]] = {
    "stdlib/adapters.rdis": {"AdapterDecl": 9},
    "examples/create.rdis": {
        "RobotDecl": 1,
        "SensorDecl": 1,
        "ConnectionDecl": 1,
        "PrimitiveDecl": 4,
        "InterfaceDecl": 4,
        "InputDecl": 1,
        "OutputDecl": 1,
    },
    "examples/koala.rdis": {
        "RobotDecl": 1,
        "StateDecl": 8,
        "ConstDecl": 2,
        "SettingDecl": 3,
        "ConnectionDecl": 1,
        "PrimitiveDecl": 5,
        "InterfaceDecl": 5,
        "InputDecl": 1,
        "OutputDecl": 2,
    },
    # the protocol examples, each checked byte for byte against a published driver (tests/conformance)
    "examples/arm.rdis": {"ConnectionDecl": 1, "ConstDecl": 7, "EnumDecl": 2, "FrameDecl": 2, "InputDecl": 1,
                          "InterfaceDecl": 3, "OutputDecl": 1, "PrimitiveDecl": 5, "RobotDecl": 1, "StateDecl": 3,
                          "LinkDecl": 7, "JointDecl": 6, "TransmissionDecl": 6, "ActuatorDecl": 6},
    "examples/ax12.rdis": {"ConnectionDecl": 1, "ConstDecl": 2, "EnumDecl": 2, "FrameDecl": 1, "InterfaceDecl": 5,
                           "PrimitiveDecl": 38, "RobotDecl": 1, "SettingDecl": 1, "StateDecl": 25},
    "examples/create2.rdis": {"ConnectionDecl": 1, "ConstDecl": 5, "InputDecl": 1, "InterfaceDecl": 4,
                              "JointDecl": 3, "LinkDecl": 4, "OutputDecl": 2, "PrimitiveDecl": 17, "RobotDecl": 1,
                              "StateDecl": 75, "TransmissionDecl": 2},
    "examples/lx16a.rdis": {"ConnectionDecl": 1, "ConstDecl": 3, "FrameDecl": 2, "InterfaceDecl": 2,
                            "PrimitiveDecl": 31, "RobotDecl": 1, "StateDecl": 20},
    "examples/maestro.rdis": {"ConnectionDecl": 1, "ConstDecl": 7, "EnumDecl": 1, "FrameDecl": 1, "InputDecl": 1,
                              "InterfaceDecl": 5, "OutputDecl": 1, "PrimitiveDecl": 8, "RobotDecl": 1,
                              "SettingDecl": 2, "StateDecl": 3},
    "examples/motoron.rdis": {"ConnectionDecl": 1, "ConstDecl": 1, "EnumDecl": 1, "FrameDecl": 1, "InterfaceDecl": 3,
                              "PrimitiveDecl": 6, "RobotDecl": 1, "SettingDecl": 4, "StateDecl": 2},
    "examples/nmea.rdis": {"ConnectionDecl": 1, "ConstDecl": 2, "FrameDecl": 3, "InterfaceDecl": 2,
                           "PrimitiveDecl": 6, "RobotDecl": 1, "StateDecl": 20},
    "examples/firmata.rdis": {"ConnectionDecl": 1, "EnumDecl": 1, "FrameDecl": 4, "InterfaceDecl": 3,
                              "PrimitiveDecl": 11, "RobotDecl": 1, "StateDecl": 10},
    "examples/kobuki.rdis": {"ConnectionDecl": 1, "FrameDecl": 2, "InterfaceDecl": 2, "PrimitiveDecl": 2,
                             "RobotDecl": 1, "StateDecl": 12},
    "examples/rplidar.rdis": {"ConnectionDecl": 1, "FrameDecl": 2, "InterfaceDecl": 2, "PrimitiveDecl": 8,
                              "RobotDecl": 1, "StateDecl": 11},
    "examples/roboclaw.rdis": {"ConnectionDecl": 1, "FrameDecl": 3, "InterfaceDecl": 1, "PrimitiveDecl": 32,
                               "RobotDecl": 1, "SettingDecl": 1, "StateDecl": 19},
    "examples/modbus.rdis": {"RobotDecl": 1, "EnumDecl": 1, "SettingDecl": 1, "StateDecl": 3, "ConnectionDecl": 1,
                             "FrameDecl": 1, "PrimitiveDecl": 3},
    "examples/tmcl.rdis": {"RobotDecl": 1, "EnumDecl": 2, "SettingDecl": 2, "StateDecl": 4, "ConnectionDecl": 1,
                           "FrameDecl": 1, "PrimitiveDecl": 10, "InterfaceDecl": 2},
    "examples/um7.rdis": {"RobotDecl": 1, "ConstDecl": 2, "StateDecl": 11, "ConnectionDecl": 1, "FrameDecl": 2,
                          "PrimitiveDecl": 9},
    "examples/tfmini.rdis": {"RobotDecl": 1, "ConstDecl": 2, "StateDecl": 3, "ConnectionDecl": 1, "FrameDecl": 2,
                             "PrimitiveDecl": 3, "InterfaceDecl": 2},
    "examples/sabertooth.rdis": {"RobotDecl": 1, "SettingDecl": 1, "StateDecl": 1, "ConnectionDecl": 1,
                                 "FrameDecl": 1, "PrimitiveDecl": 3, "InterfaceDecl": 3},
    "examples/crsf.rdis": {"RobotDecl": 1, "StateDecl": 15, "ConnectionDecl": 1, "FrameDecl": 2, "PrimitiveDecl": 4,
                           "InterfaceDecl": 1},
    "examples/sbus.rdis": {"RobotDecl": 1, "StateDecl": 5, "ConnectionDecl": 1, "FrameDecl": 2, "PrimitiveDecl": 2},
    "examples/slcan.rdis": {"RobotDecl": 1, "ConstDecl": 3, "StateDecl": 10, "ConnectionDecl": 1, "FrameDecl": 1,
                            "PrimitiveDecl": 14, "InterfaceDecl": 1},
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
    "JointState": (
        "sensor_msgs/JointState",
        {"name": ("string[]", None, "name"), "position": ("float[]", "rad", "position")},
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
        assert adapter.ros is not None and adapter.ros.value == message, name
        got = {f.name.text: (print_type(f.type), f.unit, f.ros.value if f.ros else None) for f in adapter.fields}
        assert got == fields, name


def test_standard_adapters_are_documented() -> None:
    module = _parse(STDLIB)
    for adapter in module.decls:
        assert isinstance(adapter, ast.AdapterDecl), "the stdlib declares adapters only"
        assert adapter.doc, f"adapter {adapter.name.text} has no /// doc comment"
        for f in adapter.fields:
            assert f.doc, f"field {adapter.name.text}.{f.name.text} has no /// doc comment"
            if print_type(f.type) in ("int", "float", "int[]", "float[]"):
                assert f.unit, f"numeric field {adapter.name.text}.{f.name.text} has no unit"
    odometry = _decl(module, ast.AdapterDecl, "Odometry")
    assert ":yaw" in odometry.doc
    assert "Celsius" in _decl(module, ast.AdapterDecl, "Temperature").doc
