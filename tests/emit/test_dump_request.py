"""`rdisc dump FILE PRIMITIVE --args K=V ...`: the bytes of one request, made by the engine as a
call makes them, held against the primitive's byte table row by row; a value refused as a call
refuses it is said in one line, exit 2, and nothing is printed."""

from __future__ import annotations

from pathlib import Path

import pytest

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


def test_a_create_drive_request_field_by_field(rdisc) -> None:
    result = rdisc("dump", EXAMPLES / "create.rdis", "drive", "--args", "velocity=200", "radius=-1")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
primitive drive(velocity=200, radius=-1) on btserial: 5 bytes
  89 00 C8 FF FF
  offset  size  kind                  value                         holds         bytes
       0     1  u8                    89 (137)                      137           89
       1     2  s16 BE                velocity                      200           00 C8
       3     2  s16 BE                radius                        -1            FF FF
"""


def test_an_ax12_goal_framed_with_its_length_and_checksum(rdisc) -> None:
    """The AX-12 manual's WRITE of goal position 512 to servo 1: FF FF 01 05 03 1E 00 02 D6."""
    result = rdisc("dump", EXAMPLES / "ax12.rdis", "goto", "--args", "id=1", "--args", "goal=0x200")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
primitive goto(id=1, goal=512) on bus: 9 bytes
  FF FF 01 05 03 1E 00 02 D6
  offset  size  kind                  value                         holds         bytes
       0     2  header                FF FF                                       FF FF
       2     1  field id              "B" = id                      1             01
       3     1  length                "B" = payload + 1             5             05
       4     1  payload u8            03 (3)                        3             03
       5     1  payload u8            1E (30)                       30            1E
       6     2  payload u16 LE        goal                          512           00 02
       8     1  checksum              sum inverted as B, over id .. payload                D6
"""


def test_text_takes_the_size_the_others_leave(rdisc) -> None:
    result = rdisc("dump", EXAMPLES / "koala.rdis", "set_speed", "--args", "left=10", "right=-3")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout.splitlines()[1:] == [
        "  44 2C 31 30 2C 2D 33 0A",
        "  offset  size  kind                  value                         holds         bytes",
        '       0     8  text                  "D,{},{}\\n" (left, right)     "D,10,-3\\n"   44 2C 31 30 2C 2D 33 0A',
    ]


def test_a_stuffed_frame_shows_its_bytes_whole(rdisc) -> None:
    result = rdisc("dump", EXAMPLES / "arm.rdis", "sync_torque", "--args", "on=1,0,1,0,1,0")
    assert (result.returncode, result.stderr) == (0, "")
    assert result.stdout == """\
primitive sync_torque(on=(1, 0, 1, 0, 1, 0)) on bus: 26 bytes
  FF FF FD 00 FE 13 00 83 40 00 01 00 01 01 02 00 03 01 04 00 05 01 06 00 11 69
  (stuffed, escaped or of sizes the table cannot tell: the bytes whole)
"""


@pytest.mark.parametrize(("words", "said"), [
    (["read_position", "--args", "id=300"], "rdisc dump: read_position: frame dxl: parameter id is 300, outside 0..254"),
    (["read_position", "--args", "idx=3"], "rdisc dump: primitive read_position: unexpected argument 'idx'"),
    (["read_position", "--args", "id=zz"], "rdisc dump: primitive read_position: parameter id must be int, not str 'zz'"),
    (["read_position", "--args", "id"], "rdisc dump: --args `id` is not KEY=VALUE"),
    (["read_position", "--args", "id=1", "id=2"], "rdisc dump: --args `id` given twice"),
    (["goto", "--args", "id=1"], "rdisc dump: primitive goto: missing argument 'goal'"),
    (["goto", "--args", "id=1", "goal=1" + "0" * 30],
     "rdisc dump: primitive goto: parameter goal is a 100-bit integer; integers are limited to 64 bits and a sign"),
    (["--args", "id=1"], "rdisc dump: --args needs a PRIMITIVE to make a request of"),
])
def test_refused_arguments_are_one_line_and_exit_2(rdisc, words: list[str], said: str) -> None:
    result = rdisc("dump", EXAMPLES / "ax12.rdis", *words)
    assert (result.returncode, result.stdout, result.stderr) == (2, "", said + "\n")


def test_an_unknown_primitive_names_the_known_ones(rdisc) -> None:
    result = rdisc("dump", EXAMPLES / "create.rdis", "drve")
    assert (result.returncode, result.stdout, result.stderr) == (
        2, "", "rdisc dump: irobot_create has no primitive `drve` (its primitives: start, full, drive, bumpers)\n")


def test_the_bytes_are_those_a_call_writes() -> None:
    """`Robot.request` is the call's own path: a port given the same call receives the same bytes."""
    from rdisc.runtime.device import load
    from tests.support.ports import ScriptedPort

    description = load(EXAMPLES / "ax12.rdis")
    port = ScriptedPort(bytes.fromhex("ffff010200fc"))
    robot = description.connect(port, threads=False)
    try:
        before = len(port.written)
        robot.call_primitive("goto", 1, 512)
        assert bytes(port.written[before:]) == robot.request("goto", 1, 512) == bytes.fromhex("ffff010503 1e0002d6")
    finally:
        robot.close()
