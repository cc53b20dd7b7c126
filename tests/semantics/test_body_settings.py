"""Settings in the body (issue 26: "a wheel base given when connecting"): a body's size, place or
limit may read a number setting. The checks, URDF, SDF, MJCF, ros2_control and `rdisc sim` take its
default, or the value `--set NAME=VALUE` gives (held to the setting's type and range as `rdisc
run` holds it: a usage error else); a setting of another type is E213, an unknown name E103."""

from __future__ import annotations

import json
import xml.etree.ElementTree as ET
from pathlib import Path

from rdisc.compile import compile_path
from tests.conftest import run_rdisc

# A differential drive whose wheel base and top speed are given when connecting; its input
# uses the same wheel base, so the drive agrees with its body whatever the value.
DRIVE = """\
robot rover { author "tests" }
connection c: serial { baud 9600 }
const R = 0.036
/// Between the wheels, in metres.
setting TRACK: float in 0.1..1.0 = 0.235
setting TOP: float in 1..20 = 13.8
setting LABEL: string = "rover"
primitive wheels(right: int in -500..500 unit "mm/s", left: int in -500..500 unit "mm/s") on c pack ">hh" (right, left)
interface drive(right: float, left: float) { wheels(round(right * 1000), round(left * 1000)) }
input go: DifferentialSpeed -> drive(linear + angular * TRACK / 2, linear - angular * TRACK / 2)
link base { collision box(0.3, TRACK, 0.05) at [0, 0, 0.05]  mass 3  inertia [0.02, 0.02, 0.04] }
link left { collision cylinder(R, 0.02) rpy [1.5707963267948966, 0, 0]  mass 0.1  inertia [0.001, 0.001, 0.001] }
link right { collision cylinder(R, 0.02) rpy [1.5707963267948966, 0, 0]  mass 0.1  inertia [0.001, 0.001, 0.001] }
joint left_joint: continuous base -> left { at [0, TRACK / 2, R] axis [0, 1, 0] velocity TOP effort 0.5 }
joint right_joint: continuous base -> right { at [0, -TRACK / 2, R] axis [0, 1, 0] velocity TOP effort 0.5 }
transmission l: left_joint { command velocity to wheels.left { raw = round(velocity * R * 1000)  velocity = raw / 1000 / R } }
transmission r: right_joint { command velocity to wheels.right { raw = round(velocity * R * 1000)  velocity = raw / 1000 / R } }
"""


def _write(tmp_path: Path, text: str = DRIVE) -> Path:
    path = tmp_path / "rover.rdis"
    path.write_text(text, encoding="utf-8")
    return path


def _errors(path: Path, **settings: float) -> list[tuple[str, str, str]]:
    compilation = compile_path(str(path), settings=settings or None)
    text = path.read_text(encoding="utf-8")
    return [(d.code, text[d.span.start:d.span.end], d.message) for d in compilation.diagnostics.sorted()
            if d.severity == 1]


def test_the_body_takes_a_setting_s_default_or_the_value_given(tmp_path: Path) -> None:
    path = _write(tmp_path)
    default = compile_path(str(path)).model
    given = compile_path(str(path), settings={"TRACK": 0.3}).model
    assert default is not None and given is not None
    assert default.joints["left_joint"].origin.xyz == (0, 0.1175, 0.036)
    assert given.joints["left_joint"].origin.xyz == (0, 0.15, 0.036)
    assert given.joints["right_joint"].origin.xyz == (0, -0.15, 0.036)
    assert given.links["base"].collisions[0].size == (0.3, 0.3, 0.05)
    assert given.settings["TRACK"].default == 0.3  # the value given stands for the default


def test_the_checks_use_the_value_given(tmp_path: Path) -> None:
    """The input's wheel base a constant, the body's a setting: they agree at the default, and a
    wheel base given otherwise is the drive disagreeing with its body (E613)."""
    path = _write(tmp_path, DRIVE.replace("angular * TRACK / 2", "angular * 0.235 / 2"))
    assert _errors(path) == []
    assert _errors(path, TRACK=0.3) == [
        ("E613", "go", ("a counter-clockwise command of 0.5 rad/s to input `go` turns the body's base at 0.3933 rad/s: "
         "the input gives the wheels' speeds as if they were 0.236 m apart, the body's wheel joints are 0.3 m apart"))]


def test_a_setting_that_is_not_a_number_or_not_declared_is_refused(tmp_path: Path) -> None:
    path = _write(tmp_path, DRIVE.replace("box(0.3, TRACK, 0.05)", "box(0.3, LABEL, 0.05)")
                  .replace("velocity TOP effort 0.5 }\njoint right", "velocity TOPP effort 0.5 }\njoint right"))
    compilation = compile_path(str(path))
    found = [(d.code, d.message, d.help) for d in compilation.diagnostics.sorted() if d.severity == 1]
    assert found == [
        ("E213", "setting `LABEL` is a string: a box's y is a number",
         "a body's sizes, places and masses may read number settings"),
        ("E103", "unknown name `TOPP` in the body", "did you mean `TOP`?"),
    ]


def test_urdf_sdf_mjcf_and_ros2_control_are_written_with_the_value_given(tmp_path: Path) -> None:
    path = _write(tmp_path)
    urdf = run_rdisc("emit-urdf", path, "--ros2-control", "--set", "TRACK=0.3", "--set", "TOP=10")
    assert (urdf.returncode, urdf.stderr) == (0, "")
    robot = ET.fromstring(urdf.stdout)
    origin = robot.find("joint[@name='left_joint']/origin")
    limit = robot.find("joint[@name='left_joint']/limit")
    low = robot.find("ros2_control/joint[@name='left_joint']/command_interface/param[@name='min']")
    assert origin is not None and limit is not None and low is not None
    assert (origin.get("xyz"), limit.get("velocity"), low.text) == ("0 0.15 0.036", "10", "-10")
    sdf = run_rdisc("emit-sdf", path, "--set", "TRACK=0.3")
    assert sdf.returncode == 0, sdf.stderr
    pose = ET.fromstring(sdf.stdout).find(".//joint[@name='left_joint']/pose")
    assert pose is not None and pose.text is not None and pose.text.split()[:3] == ["0", "0.15", "0.036"]
    mjcf = run_rdisc("emit-mjcf", path, "--set", "TRACK=0.3")
    assert mjcf.returncode == 0, mjcf.stderr
    body = ET.fromstring(mjcf.stdout).find(".//body[@name='left']")
    assert body is not None and body.get("pos") == "0 0.15 0.036"
    plain = run_rdisc("emit-urdf", path)
    assert 'xyz="0 0.1175 0.036"' in plain.stdout


def test_a_value_given_that_does_not_fit_is_a_usage_error(tmp_path: Path) -> None:
    path = _write(tmp_path)
    for given, said in (("TRACK=3", "rdisc emit-urdf: rover: setting TRACK is 3.0, outside 0.1..1.0"),
                        ("TRAKC=0.3", ("rdisc emit-urdf: rover: no setting named 'TRAKC' (its settings: TRACK, TOP, "
                                      "LABEL)")),
                        ("TRACK=wide", "rdisc emit-urdf: rover: setting TRACK must be float, not str 'wide'")):
        done = run_rdisc("emit-urdf", path, "--set", given)
        assert (done.returncode, done.stdout, done.stderr.strip()) == (2, "", said)
    done = run_rdisc("sim", path, "--set", "TRACK=3")
    assert (done.returncode, done.stderr.strip()) == (2, "rdisc sim: rover: setting TRACK is 3.0, outside 0.1..1.0")


def test_a_setting_without_a_default_is_reported_once_where_it_is_declared(tmp_path: Path) -> None:
    """Before, the body computed with no value: an internal error."""
    path = _write(tmp_path, DRIVE.replace("setting TRACK: float in 0.1..1.0 = 0.235", "setting TRACK: float"))
    assert [(code, text) for code, text, _ in _errors(path)] == [("E213", "TRACK")]


# DRIVE with a setting in a colour, a mass, a mimic and an actuator's velocity too.
LINKED = (DRIVE.replace("link base { collision", "link base { visual box(0.3, 0.2, 0.05) color [TRACK, 0, 0]  collision")
          .replace("mass 3 ", "mass 10 * TRACK ")
          .replace("velocity TOP effort 0.5 }\njoint right", "velocity TOP effort 0.5 mimic right_joint multiplier "
                   "TOP / 13.8 }\njoint right")
          .replace("transmission l: left_joint {", "actuator motor: wheel { velocity TOP }\n"
                   "transmission l: left_joint actuator motor {"))


def test_canonical_json_carries_what_the_body_reads_so_a_value_given_moves_it_as_in_the_rdis(tmp_path: Path) -> None:
    """Before, the JSON had the body's numbers at the defaults: `--set` on it moved nothing."""
    path = _write(tmp_path, LINKED)
    built = run_rdisc("build", path)
    assert (built.returncode, built.stderr) == (0, "")
    document = json.loads(built.stdout)
    base, left, _ = document["links"]
    assert base["visuals"][0]["color"] == ["<TRACK>", 0, 0]  # as written: alpha 1 left out
    assert base["collisions"][0] == {"shape": "box", "size": [0.3, "<TRACK>", 0.05], "xyz": [0, 0, 0.05]}
    assert base["inertial"]["mass"] == "<10 * TRACK>"
    assert left["collisions"][0]["size"] == [0.036, 0.02]  # reads no setting: its numbers
    joint = document["joints"][0]
    assert (joint["xyz"], joint["velocity"], joint["mimic"]) == (
        [0, "<TRACK / 2>", 0.036], "<TOP>", {"joint": "right_joint", "multiplier": "<TOP / 13.8>", "offset": 0})
    assert document["joints"][1]["xyz"] == [0, "<-TRACK / 2>", 0.036]
    assert document["actuators"][0]["velocity"] == "<TOP>"
    described = tmp_path / "rover.json"
    described.write_text(built.stdout, encoding="utf-8")
    for verb in ("emit-urdf", "emit-sdf", "emit-mjcf"):
        given = [run_rdisc(verb, source, "--set", "TRACK=0.3", "--set", "TOP=10") for source in (path, described)]
        assert [(each.returncode, each.stderr) for each in given] == [(0, ""), (0, "")]
        assert given[1].stdout == given[0].stdout.replace("rover.rdis", "rover.json")
        assert given[1].stdout != run_rdisc(verb, described).stdout.replace("rover.rdis", "rover.json")
    imported = tmp_path / "imported.rdis"
    assert run_rdisc("import", described, "-o", imported).returncode == 0
    assert "    at [0, TRACK / 2, 0.036]\n" in imported.read_text(encoding="utf-8")
    again = run_rdisc("build", imported)
    assert (again.returncode, again.stderr, again.stdout) == (0, "", built.stdout)
