"""E613 against the odometry (issue 26): an `Odometry` output integrated by a primitive's
post-actions from the two wheels' encoder counts must move as the body's wheels roll for them, its
wheel radius and wheel base the body's; decided by the checker from the expressions, not simulated.
The issue's case: an odometry counting with a 0.036 m radius on 0.044 m wheels (0.396 m said where
the base went 0.485 m)."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path

ROOT = Path(__file__).resolve().parents[2]
RIGHT = "const M_PER_COUNT = WHEEL_RADIUS / COUNTS_PER_RAD"

# Encoders in 1/1000 rad; the odometry integrates them at its own radius ODOM_R and wheel base ODOM_TRACK.
ROVER = """\
robot rover { author "tests" }
connection c: serial { baud 115200 }
const R = 0.044
const TRACK = 0.235
const ODOM_R = 0.044
setting ODOM_TRACK: float in 0.1..1.0 = 0.235
state left_count: int  state right_count: int
state odom_x: float  state odom_y: float  state odom_theta: float
primitive counts() on c pack "B" (1) unpack ">hh" {
    odom_x = odom_x + ((out[0] - left_count) + (out[1] - right_count)) / 1000 * ODOM_R / 2 * cos(odom_theta)
    odom_y = odom_y + ((out[0] - left_count) + (out[1] - right_count)) / 1000 * ODOM_R / 2 * sin(odom_theta)
    odom_theta = odom_theta + ((out[1] - right_count) - (out[0] - left_count)) / 1000 * ODOM_R / ODOM_TRACK
    left_count = out[0]  right_count = out[1]
}
interface poll() periodic triggers odom { counts() }
output odom: Odometry { x = odom_x  y = odom_y  theta = odom_theta  linear = 0.0  angular = 0.0 }
link base { mass 3  inertia [0.02, 0.02, 0.04] }
link left { collision cylinder(R, 0.02) rpy [1.5707963267948966, 0, 0]  mass 0.1  inertia [0.001, 0.001, 0.001] }
link right { collision cylinder(R, 0.02) rpy [1.5707963267948966, 0, 0]  mass 0.1  inertia [0.001, 0.001, 0.001] }
joint left_joint: continuous base -> left { at [0, TRACK / 2, R] axis [0, 1, 0] }
joint right_joint: continuous base -> right { at [0, -TRACK / 2, R] axis [0, 1, 0] }
transmission l: left_joint { measure position from left_count { raw = round(position * 1000)  position = raw / 1000 } }
transmission r: right_joint { measure position from right_count { raw = round(position * 1000)  position = raw / 1000 } }
"""

RADIUS = ("output `odom` says 100 counts of each wheel's encoder move the base 0.0036 m, but the body's wheels roll "
          "it 0.0044 m: the odometry's wheel radius is 0.036 m, the body's wheels are 0.044 m")


def _found(tmp_path: Path, text: str, **settings: float) -> list[tuple[str, str, str, list[tuple[str, str]]]]:
    path = tmp_path / "rover.rdis"
    path.write_text(text, encoding="utf-8")
    compilation = compile_path(str(path), settings=settings or None)
    written = path.read_text(encoding="utf-8")
    return [(d.code, written[d.span.start:d.span.end], d.message,
             [(written[label.span.start:label.span.end][:24], label.message) for label in d.labels])
            for d in compilation.diagnostics.sorted() if d.severity == 1]


@pytest.mark.parametrize(("old", "new", "expected"), [
    ("", "", []),
    # the case: the odometry counts a 0.036 m wheel, the body's is 0.044 m
    ("const ODOM_R = 0.044", "const ODOM_R = 0.036",
     [("E613", "odom", RADIUS, [("odom_x = odom_x + ((out[", "the odometry's step, in `counts`"),
                                ("collision cylinder(R, 0.", "the body's wheel, radius 0.044 m")])]),
    ("setting ODOM_TRACK: float in 0.1..1.0 = 0.235", "setting ODOM_TRACK: float in 0.1..1.0 = 0.3",
     [("E613", "odom", ("output `odom` says 100 counts forward of the right wheel's encoder and back of the left's "
       "turn the base 0.02933 rad, but the body turns 0.03745 rad: the odometry's wheels are 0.3 m apart, the body's "
       "wheel joints are 0.235 m apart"),
       [("odom_x = odom_x + ((out[", "the odometry's step, in `counts`"), ("left_joint", "at y = 0.1175 m"),
        ("right_joint", "at y = -0.1175 m")])]),
    # an encoder counting the other way: the odometry says backward where the body rolls forward
    ("position from right_count { raw = round(position * 1000)  position = raw / 1000 }",
     "position from right_count { raw = round(position * -1000)  position = raw / -1000 }",
     [("E613", "odom", ("output `odom` says 100 counts of each wheel's encoder move the base 0.0044 m and turn it 0 "
       "rad, but the body's wheels move it 0 m and turn it -0.03745 rad"),
       [("odom_x = odom_x + ((out[", "the odometry's step, in `counts`"),
        ("collision cylinder(R, 0.", "the body's wheel, radius 0.044 m")])]),
    # a scale the device holds (state no post-action of the step writes): known only when it runs, not judged
    ("/ 1000 * ODOM_R / 2 * cos", "/ 1000 * ODOM_R * scale / 2 * cos", []),
])
def test_the_odometry_counts_as_the_body_rolls(tmp_path: Path, old: str, new: str, expected: list[object]) -> None:
    assert old in ROVER
    text = ROVER.replace(old, new).replace("state left_count", "state scale: float = 1.25\nstate left_count")
    assert _found(tmp_path, text) == expected


def test_a_wheel_base_given_when_connecting_is_the_one_held_to_the_body(tmp_path: Path) -> None:
    assert _found(tmp_path, ROVER, ODOM_TRACK=0.235) == []
    assert [found[2] for found in _found(tmp_path, ROVER, ODOM_TRACK=0.3)] == [
        ("output `odom` says 100 counts forward of the right wheel's encoder and back of the left's turn the base "
        "0.02933 rad, but the body turns 0.03745 rad: the odometry's wheels are 0.3 m apart, the body's wheel joints "
        "are 0.235 m apart")]


def test_the_create2_s_odometry_with_25_percent_too_many_metres_a_count_is_refused(tmp_path: Path) -> None:
    text = (ROOT / "examples" / "create2.rdis").read_text(encoding="utf-8")
    assert RIGHT in text
    wrong = text.replace(RIGHT, "const M_PER_COUNT = WHEEL_RADIUS * 1.25 / COUNTS_PER_RAD")
    assert [found[:3] for found in _found(tmp_path, wrong)] == [
        ("E613", "odom", ("output `odom` says 100 counts of each wheel's encoder move the base 0.05557 m, but the "
         "body's wheels roll it 0.04446 m: the odometry's wheel radius is 0.045 m, the body's wheels are 0.036 m"))]
    assert _found(tmp_path, text) == []
