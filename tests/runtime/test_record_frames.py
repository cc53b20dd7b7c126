"""The frames a recording's stamped messages name (rdisc.semantics.ros.header_frames, which the
ROS node writes too): an output's link, the body's base without `frame`, an Odometry's pose in
the fixed `odom` frame with the link as its child frame, nothing without a body. In process: the
runtime's robot on a scripted port, recorded to memory, read back with the `mcap` readers."""

from __future__ import annotations

import io
from pathlib import Path
from typing import Any

import pytest
from mcap.reader import make_reader
from mcap_ros2.decoder import DecoderFactory
from runtime_support import DATA, EXAMPLES

from rdisc import engine
from rdisc.compile import compile_path
from rdisc.runtime import load
from rdisc.semantics.ros import header_frames
from tests.support.ports import ScriptedPort

ROVER = """\
robot rover { author "tests" }
state x: float = 0.0
connection link: serial { baud 9600 }
primitive where() on link pack "B" (1) unpack "<h" { x = out[0] / 1000 }
interface poll() triggers odom, seen { where() }
output odom: Odometry { x = x  y = 0.0  theta = 0.0  linear = 0.0  angular = 0.0 }
output seen: Range frame sonar { distance = x }
link chassis { mass 2  inertia [0.1, 0.1, 0.1] }
link sonar { collision sphere(0.01) }
joint sonar_mount: fixed chassis -> sonar { at [0.2, 0, 0.1] }
"""


@pytest.mark.parametrize(("source", "frames"), [
    (EXAMPLES / "create2.rdis", {"odom": ("odom", "base"), "battery": ("base", "")}),
    (DATA / "framed_create.rdis", {"detect_bump": ("bumper", ""), "base_bump": ("base", "")}),
    (EXAMPLES / "koala.rdis", {"odometry": ("", ""), "obstacle": ("", "")}),  # no body
], ids=["create2", "framed_create", "koala"])
def test_each_output_s_frames(source: Path, frames: dict[str, tuple[str, str]]) -> None:
    model = compile_path(str(source)).model
    assert model is not None
    assert {name: header_frames(model, o) for name, o in model.outputs.items()} == frames


def test_a_recorded_odometry_is_in_odom_with_its_link_as_child(tmp_path: Path) -> None:
    source = tmp_path / "rover.rdis"
    source.write_text(ROVER, encoding="utf-8")
    robot = engine.Robot(load(source).device)
    delivered: list[Any] = []
    robot.on_output(delivered.append)
    stream = io.BytesIO()
    recorder = engine.Recorder(robot, stream)
    robot.open(ScriptedPort(b"\xe8\x03"), threads=False)  # x = 1000 mm
    try:
        robot.call_interface("poll")
    finally:
        robot.close()
        recorder.finish()
    reader = make_reader(io.BytesIO(stream.getvalue()), decoder_factories=[DecoderFactory()])
    found = {channel.topic: decoded for _, channel, _, decoded in reader.iter_decoded_messages()
             if channel.topic in ("/odom", "/seen")}
    read = delivered[0].read_ns
    odom, seen = found["/odom"], found["/seen"]
    assert (odom.header.frame_id, odom.child_frame_id, odom.pose.pose.position.x) == ("odom", "chassis", 1.0)
    assert (seen.header.frame_id, seen.range) == ("sonar", 1.0)
    for message in (odom, seen):
        assert message.header.stamp.sec * 1_000_000_000 + message.header.stamp.nanosec == read
