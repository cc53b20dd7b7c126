"""ROS names a description gives reach the ROS node as code, checked: an adapter's message
type and field paths are refused unless they are what ROS allows (E108), and the node
imports only message modules of ROS message packages, reading and writing fields by name
in its own code."""

from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import pytest
from conftest import run_rdisc

from rdisc.compile import compile_path
from rdisc.emit.ros import to_ros

EVIL = """\
robot evil { author "tests" }
state hit: bool = False
connection c: serial { baud 9600 }
primitive bumps() on c pack "BB" (142, 7) unpack "B" { hit = out[0] != 0 }
adapter Evil ros "this/Bool" { hit: bool ros "__class__.__init__" }
interface poll() periodic triggers bumped { bumps() }
output bumped: Evil { hit = hit }
"""


def test_the_evil_adapter_of_the_issue_is_refused(tmp_path: Path) -> None:
    source = tmp_path / "evil.rdis"
    source.write_text(EVIL, encoding="utf-8")
    result = run_rdisc("check", source)
    assert result.returncode == 1
    assert result.stderr.startswith(
        "error[E108]: `__class__` in `__class__.__init__` is not a ROS field: a name of letters, digits and "
        "underscores that starts with a letter, optionally with a list item `[i]`\n"
        f" --> {source}:5:46\n"
    ), result.stderr
    assert result.stderr.count("error[") == 1


@pytest.mark.parametrize(("annotation", "problem"), [
    ('adapter A ros "std_msgs" { x: float }', "`std_msgs` is not a ROS message type"),
    ('adapter A ros "Std_msgs/Bool" { x: float }', "`Std_msgs/Bool` is not a ROS message type"),
    ('adapter A ros "std_msgs/bool" { x: float }', "`std_msgs/bool` is not a ROS message type"),
    ('adapter A ros "std_msgs/Bool.x" { x: float }', "`std_msgs/Bool.x` is not a ROS message type"),
    ('adapter A ros "os/System" { x: float ros "data" }', None),  # a package name: checked at the node's start
    ('adapter A ros "std_msgs/Float64" { x: float ros "_data" }', "`_data` in `_data` is not a ROS field"),
    ('adapter A ros "std_msgs/Float64" { x: float ros "data[1024]" }', "list item `[1024]` in `data[1024]`"),
    ('adapter A ros "std_msgs/Float64" { x: float ros "a..b" }', "`` in `a..b` is not a ROS field"),
    ('adapter A ros "std_msgs/Float64" { x: float ros "a.import" }', "`import` in `a.import` is a Python keyword"),
    ('adapter A ros "nav_msgs/Odometry" { x: float ros "pose.pose.orientation:eval" }',
     "`:eval` is not a conversion of a field path"),
    ('adapter A ros "nav_msgs/Odometry" { x: float ros "pose.pose.orientation:yaw" }', None),
    ('adapter A ros "sensor_msgs/JointState" { x: float ros "position[3]" }', None),
])
def test_ros_names_are_checked_as_what_they_are(tmp_path: Path, annotation: str, problem: str | None) -> None:
    source = tmp_path / "a.rdis"
    source.write_text('robot r { author "tests" }\n' + annotation + "\n", encoding="utf-8")
    compilation = compile_path(str(source))
    errors = [d for d in compilation.diagnostics.items if d.severity.name == "ERROR"]
    if problem is None:
        assert errors == []
    else:
        assert [d.code for d in errors] == ["E108"]
        assert errors[0].message.startswith(problem), errors[0].message


def test_the_node_imports_no_module_that_is_not_a_ros_message_package(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]) -> None:
    """`this/Bool` is a well-formed name, but `this` is a module of the standard library (it
    prints a poem when imported): the node finds that it holds no `msg/_Bool.py` and stops
    before importing anything."""
    source = tmp_path / "poem.rdis"
    source.write_text(EVIL.replace('ros "__class__.__init__"', 'ros "data"'), encoding="utf-8")
    compilation = compile_path(str(source))
    assert compilation.model is not None
    node = tmp_path / "poem_node.py"
    node.write_text(to_ros(compilation.model, "poem.rdis", sources=compilation.sources), encoding="utf-8")
    assert '        ("this", "Bool"),\n' in node.read_text(encoding="utf-8")
    spec = importlib.util.spec_from_file_location("poem_node", node)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    monkeypatch.setitem(sys.modules, "poem_node", module)  # its dataclasses look their module up there
    spec.loader.exec_module(module)
    already = "this" in sys.modules
    with pytest.raises(SystemExit) as exited:
        module.ros_main()
    assert exited.value.code == 2
    said = capsys.readouterr().err.splitlines()
    assert any(line.endswith(": this/Bool is not a ROS message here: install its package") for line in said), said
    assert already or "this" not in sys.modules
