"""The body's checks (rdisc/semantics/body.py), each with its exact diagnostic: where it points,
what it says, and the help, the did-you-mean and the labels that show both sides."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.compile import compile_path

HEAD = 'robot r { author "t" }\nconnection c: serial { baud 9600 }\n'
# A servo arm's device: a goal in 0..1023, a float speed, a string label; state read back.
DEVICE = (
    "link base {}\nlink arm { mass 1  inertia [0.1, 0.1, 0.1] }\n"
    "joint lift: revolute base -> arm { limit -1.5..1.5 velocity 2 effort 1 axis [0, 0, 1] }\n"
    "state pos: int\nstate many: int[3]\nstate name: string\nsetting gain: float = 1.0\n"
    'primitive servo(goal: int in 0..1023, speed: float, label: string) on c pack ">Hf" (goal, speed)\n'
    'primitive read() on c pack "B" (1) unpack ">hhhh" { pos = out[0]  many = [out[1], out[2], out[3]] }\n'
    "interface poll() periodic { read() }\n"
    'interface move(target: float) { servo(round(target), 1.0, "") }\n'
)

Found = tuple[str, str, str]  # code, the text it points at, message


def check(tmp_path: Path, body: str) -> list[tuple[str, str, str, str | None, list[tuple[str, str]]]]:
    """The errors of a description, each as (code, the text it points at, message, help, labels)."""
    text = HEAD + body
    path = tmp_path / "body.rdis"
    path.write_text(text, encoding="utf-8")
    compilation = compile_path(str(path))
    return [(d.code, text[d.span.start:d.span.end], d.message, d.help,
             [(text[label.span.start:label.span.end], label.message) for label in d.labels])
            for d in compilation.diagnostics.sorted() if d.severity == 1]


def errors(tmp_path: Path, body: str) -> list[Found]:
    return [found[:3] for found in check(tmp_path, body)]  # type: ignore[misc]


TREE = [
    ("link a {}\nlink b {}\njoint ab: fixed a -> b {}\njoint ba: fixed b -> a {}\n",
     [("E601", "a", "the links form a cycle with no root")]),
    (("link base {}\nlink a {}\nlink b {}\nlink c {}\njoint ab: fixed a -> b {}\njoint ba: fixed b -> a {}\n"
     "joint bc: fixed b -> c {}\n"),
     [("E601", "ab", "joint `ab` closes a cycle: links `b`, `a` hang from each other, not from the root `base`")]),
    (("link base {}\nlink a {}\nlink b {}\njoint one: fixed base -> b {}\njoint two: fixed a -> b {}\n"
     "joint three: fixed base -> a {}\n"),
     [("E601", "b", "link `b` is the child of two joints")]),
    ("link base {}\nlink a {}\nlink lost {}\nlink x {}\njoint j: fixed base -> a {}\njoint lx: fixed lost -> x {}\n",
     [("E601", "lost", "link `lost` is not joined to the tree of `base`")]),
    ("link base {}\njoint j: fixed base -> base {}\n", [("E601", "base", "joint `j` joins link `base` to itself")]),
    ("link base {}\nlink wheel {}\njoint j: fixed bsae -> wheell {}\n",
     [("E102", "bsae", "unknown link `bsae`"), ("E102", "wheell", "unknown link `wheell`")]),
]

SHAPES = [
    ("link base { visual cylnder(0.1, 0.2) }\n", [("E602", "cylnder", "unknown shape `cylnder`")]),
    ("link base { visual cylinder(0.1) }\n",
     [("E602", "cylinder(0.1)", "cylinder takes 2 sizes (radius, length), not 1")]),
    ("link base { visual box(0.1, 0, -1) }\n",
     [("E602", "0", "a box's y must be more than 0, not 0"), ("E602", "-1", "a box's z must be more than 0, not -1")]),
    ('link base { visual sphere(1) at [0, 0] collision sphere(1) at 5 }\n',
     [("E602", "[0, 0]", "a position is three numbers, `[x, y, z]`, not 2"),
      ("E602", "5", "a position must be constant finite numbers, written `[x, y, z]`")]),
    ('link base { visual mesh("") collision mesh("a.stl", 0) visual mesh("a.stl", [1, 0, 1]) }\n',
     [("E602", 'mesh("")', 'a mesh is `mesh("file")` or `mesh("file", scale)`'),
      ("E602", "0", "a mesh's scale must be more than 0, not 0"),
      ("E602", "[1, 0, 1]", "a mesh's scale must be more than 0")]),
]

JOINTS = [
    ("link base {}\nlink a {}\njoint j: revolut base -> a {}\n", [("E603", "revolut", "unknown joint kind `revolut`")]),
    ("link base {}\nlink a {}\njoint j: continuous base -> a { axis [0, 0, 0] }\n",
     [("E603", "[0, 0, 0]", "an axis must not be zero")]),
    ("link base {}\nlink a {}\njoint j: revolute base -> a { limit 1..-1 velocity 1 effort 1 }\n",
     [("E603", "limit 1..-1", "a joint's limits are ordered, low < high, not 1..-1")]),
    ("link base {}\nlink a {}\njoint j: prismatic base -> a { axis [1, 0, 0] }\n",
     [("E603", "j", "prismatic joint `j` has no `limit LOW..HIGH`"),
      ("E603", "j", "prismatic joint `j` has no `velocity`"),
      ("E603", "j", "prismatic joint `j` has no `effort`")]),
    ("link base {}\nlink a {}\njoint j: continuous base -> a { limit -1..1 }\n",
     [("E603", "limit -1..1", "a continuous joint has no position limit")]),
    ("link base {}\nlink a {}\njoint j: fixed base -> a { axis [0, 0, 1] velocity 1 limit 0..1 }\n",
     [("E603", "axis [0, 0, 1]", "a fixed joint does not move: it has no `axis`"),
      ("E603", "velocity 1", "a fixed joint does not move: it has no `velocity`"),
      ("E603", "limit 0..1", "a fixed joint does not move: it has no `limit`")]),
    ("link base {}\nlink a {}\njoint j: continuous base -> a { velocity 0 damping -1 friction 0 }\n",
     [("E603", "0", "a joint's velocity must be more than 0, not 0"),
      ("E603", "-1", "a joint's damping must be 0 or more, not -1")]),
    ("link base {}\nlink a {}\njoint j: continuous base -> a { velocity 1 velocity 2 }\n",
     [("E203", "velocity 2", "`velocity` is given twice in `j`")]),
]

INERTIALS = [
    ("link base { mass 1 }\n", [("E604", "1", "link `base` has no inertia")]),
    ("link base { inertia [1, 1, 1] }\n", [("E604", "[1, 1, 1]", "link `base` has no mass")]),
    ("link base { centre [0, 0, 0] }\n", [("E604", "[0, 0, 0]", "link `base` has a centre of mass but no mass")]),
    ("link base { mass 0 inertia [1, 1, 1] }\n", [("E604", "0", "a link's mass must be more than 0, not 0")]),
    ("link base { mass 1 inertia [1, 1, 1, 2, 0, 0] }\n",
     [("E604", "[1, 1, 1, 2, 0, 0]", "the inertia is not positive definite: its principal moments are 3, 1, -1")]),
    ("link base { mass 1 inertia [0.1, 0.1, 0.3] }\n",
     [("E604", "[0.1, 0.1, 0.3]",
       "the inertia breaks the triangle inequality: its principal moments 0.1 + 0.1 < 0.3")]),
    ("link base { mass 1 inertia [0.1, 0.1] }\n",
     [("E604", "[0.1, 0.1]", "an inertia is [ixx, iyy, izz] or [ixx, iyy, izz, ixy, ixz, iyz], not 2 numbers")]),
    # issue 26: libsdformat gives a moving link without a mass 1 kg; one fixed to the base may go without
    (("link base {}\nlink arm { visual box(0.1, 0.1, 0.3) }\nlink plate {}\njoint fix: fixed base -> plate {}\n"
      "joint lift: continuous base -> arm { axis [0, 1, 0] }\n"),
     [("E611", "arm", "link `arm` is moved by joint `lift` but has no mass and inertia")]),
]


def conversion(binding: str) -> str:
    return DEVICE + f"transmission t: lift {{ {binding} }}\n"


TRANSMISSIONS = [
    (conversion("command positon to servo.goal { raw = 1  positon = raw }"),
     [("E605", "positon", "unknown joint quantity `positon`")]),
    (conversion("command position to servo.gaol { raw = round(position)  position = raw }"),
     [("E605", "gaol", "primitive `servo` has no parameter `gaol`")]),
    (conversion("measure position from many { raw = round(position)  position = raw }"),
     [("E605", "many", "state variable `many` is an array int[3]: name one element, `[i]`")]),
    (conversion("measure position from many[3] { raw = round(position)  position = raw }"),
     [("E605", "3", "state variable `many` has elements 0..2, not 3")]),
    (conversion("measure position from pos[0] { raw = round(position)  position = raw }"),
     [("E605", "0", "state variable `pos` is not an array")]),
    (conversion("measure position from name { raw = round(position)  position = raw }"),
     [("E605", "name", "state variable `name` is a string, not a number")]),
    (conversion("command position to servo.label { raw = round(position)  position = raw }"),
     [("E605", "label", "parameter `servo.label` is a string, not a number")]),
    (conversion("measure position from gain { raw = position  position = raw }"),
     [("E605", "gain", "`gain` is a setting: a joint is measured by a state variable its replies set")]),
    (conversion("command position to servo.goal { raw = round(position * 300) + 512 }"),
     [("E605", "command position to servo.goal { raw = round(position * 300) + 512 }",
       "this command does not say `position = ...` (from `raw`)")]),
    (conversion("command position to servo.goal { raw = 1  position = raw  speed = 2 }"),
     [("E605", "speed", "a command converts `raw` and `position`, not `speed`")]),
    (conversion("command position to servo.goal { raw = 1  raw = 2  position = raw }"),
     [("E203", "raw = 2", "`raw` is given twice")]),
    (conversion("command position to servo.goal { raw = position * 300 + 512  position = (raw - 512) / 300 }"),
     [("E402", "position * 300 + 512", "the device's value is an int, but this is a float")]),
    (conversion('command position to servo.goal { raw = "a"  position = raw }'),
     [("E401", '"a"', "a conversion gives a number, not a string")]),
    (conversion("command position to servo.goal { raw = round(pos)  position = raw + position }"),
     [("E103", "pos", "unknown name `pos` in a conversion to the device"),
      ("E103", "position", "unknown name `position` in a conversion to the joint")]),
    (conversion("command position to sevro.goal { raw = 1  position = raw }"),
     [("E102", "sevro", "unknown primitive or interface `sevro`")]),
    (conversion("measure position from poss { raw = round(position)  position = raw }"),
     [("E102", "poss", "unknown state variable `poss`")]),
    (DEVICE + "transmission t: lfit {}\n", [("E102", "lfit", "unknown joint `lfit`")]),
    (DEVICE + "transmission t: lift {}\n", [("E605", "t", "transmission `t` neither commands nor measures joint `lift`")]),
    (DEVICE + "link hand {}\njoint wrist: fixed arm -> hand {}\ntransmission t: wrist {}\n",
     [("E605", "wrist", "joint `wrist` is fixed: there is nothing to transmit")]),
]

SIDES = "command position to servo.goal { raw = round(position * 400) + 512  position = (raw - 512) / 400 }"
# An infinity in a description: a float's bytes (`float("inf")` of a string is refused).
INFINITY = 'from_f64le(b"\\x00\\x00\\x00\\x00\\x00\\x00\\xf0\\x7f")'

AGREEMENT = [
    (conversion(SIDES),
     [("E606", SIDES, "joint `lift`'s position -1.5 becomes -88 at servo.goal, outside its range 0..1023")]),
    (conversion("command position to servo.goal { raw = round(position * 300) + 512  position = (raw - 512) / 150 }"),
     [("E606", "command position to servo.goal { raw = round(position * 300) + 512  position = (raw - 512) / 150 }",
       ("the conversions do not undo each other: position -1.5 becomes raw 62, which comes back as position -3.0, "
       "which becomes raw -388"))]),
    (conversion("command position to servo.goal { raw = round(1 / (position - position))  position = raw }"),
     [("E606", "command position to servo.goal { raw = round(1 / (position - position))  position = raw }",
       "converting position -1.5 of joint `lift` fails: division by zero")]),
    (conversion(f"command velocity to servo.speed {{ raw = velocity * {INFINITY}  velocity = raw }}"),
     [("E606", f"command velocity to servo.speed {{ raw = velocity * {INFINITY}  velocity = raw }}",
       ("converting velocity -2 of joint `lift` gives raw -inf, which comes back as velocity -inf: not a finite "
       "number"))]),
]


@pytest.mark.parametrize(("body", "expected"), TREE + SHAPES + JOINTS + INERTIALS + TRANSMISSIONS + AGREEMENT)
def test_exact_errors(tmp_path: Path, body: str, expected: list[Found]) -> None:
    assert errors(tmp_path, body) == expected


def test_names_suggest_the_closest(tmp_path: Path) -> None:
    helps = [(found[1], found[3]) for body in (TREE[5][0], SHAPES[0][0], JOINTS[0][0], TRANSMISSIONS[0][0],
                                                 TRANSMISSIONS[1][0], TRANSMISSIONS[14][0], TRANSMISSIONS[15][0],
                                                 TRANSMISSIONS[16][0])
             for found in check(tmp_path, body)]
    assert helps == [
        ("bsae", "did you mean `base`?"), ("wheell", "did you mean `wheel`?"), ("cylnder", "did you mean `cylinder`?"),
        ("revolut", "did you mean `revolute`?"), ("positon", "did you mean `position`?"),
        ("gaol", "did you mean `goal`?"), ("sevro", "did you mean `servo`?"), ("poss", "did you mean `pos`?"),
        ("lfit", "did you mean `lift`?"),
    ]


def test_the_body_and_the_device_both_shown(tmp_path: Path) -> None:
    """A limit outside what the device accepts: the joint's limit and the parameter's range, both labelled."""
    ((_, _, _, help, labels),) = check(tmp_path, conversion(SIDES))
    assert labels == [("limit -1.5..1.5", "the joint's limit"), ("0..1023", "the range the device accepts")]
    assert help == "narrow the joint's limits, or correct the conversion"


def test_two_parents_show_the_other(tmp_path: Path) -> None:
    ((_, _, _, _, labels),) = check(tmp_path, TREE[2][0])
    assert labels == [("b", "also of joint `one`")]


def test_a_range_beyond_the_largest_float_is_sampled(tmp_path: Path) -> None:
    """-1e308..1e308 is sampled without overflowing: the device's range is what refuses it."""
    body = (DEVICE.replace("limit -1.5..1.5", "limit -1e308..1e308")
            + "transmission t: lift { command position to servo.goal { raw = round(position)  position = raw } }\n")
    ((code, _, message),) = errors(tmp_path, body)
    assert (code, message) == ("E606", ("joint `lift`'s position -1e+308 becomes -10000000000000000109... at servo.goal, "
                                       "outside its range 0..1023"))


def test_a_body_that_agrees_checks_clean(tmp_path: Path) -> None:
    body = conversion("command position to servo.goal { raw = round(position * 300) + 512  position = (raw - 512) / 300 }"
                      "  measure position from many[1] { raw = round(position * 300)  position = raw / 300 }"
                      "  command velocity to move.target { raw = velocity * 2  velocity = raw / 2 }")
    assert check(tmp_path, body) == []


# Found by the fuzzer (benchmarks/fuzz.py --seed 23): numbers no float holds, and a conversion
# of unknown type, were internal errors.
@pytest.mark.parametrize(("body", "expected"), [
    ("link base { visual box(1, 1, 1) at [2 ** 1100, 0, 0] }\n",
     [("E602", "[2 ** 1100, 0, 0]", "a position must be constant finite numbers, written `[x, y, z]`")]),
    ("link base { visual box(1, 1, 1) mass 2 ** 1100 inertia [1, 1, 1] }\n",
     [("E204", "2 ** 1100", "a link's mass must be a finite number")]),
    ("link base { visual sphere(2 ** 1100) }\n",
     [("E204", "2 ** 1100", "a sphere's radius must be a finite number")]),
    # seed 41: a path no XML file can carry was an error of the URDF writer, not of the checker
    ('link base { visual mesh("a\\x01.stl") }\n',
     [("E602", '"a\\x01.stl"', "a mesh's path has a character no URDF or SDF file can carry: '\\x01'")]),
    # seed 43: a parameter of an unknown type, commanded
    (DEVICE.replace("goal: int in", "goal: reply in") + "transmission t: lift { command position to servo.goal "
     "{ raw = round(position)  position = raw } }\n",
     [("E105", "reply", "unknown type `reply`")]),
    (DEVICE + "transmission t: lift { command position to servo.goal { raw = round(position * undefined)  "
     "position = raw } }\n",
     [("E103", "undefined", "unknown name `undefined` in a conversion to the device")]),
])
def test_values_no_output_can_hold_are_refused_not_crashed_on(tmp_path: Path, body: str, expected: list[Found]) -> None:
    assert errors(tmp_path, body) == expected


# issue 26: a differential drive, its body against the input that drives it. Each wheel's speed
# is in mm/s at the rim (`raw = round(velocity * R * 1000)`), the input maps a Twist to them.
DRIVE = """\
const R = 0.036
const TRACK = 0.235
primitive wheels(right: int in -500..500 unit "mm/s", left: int in -500..500 unit "mm/s") on c pack ">hh" (right, left)
interface drive(right: float, left: float) { wheels(round(right * 1000), round(left * 1000)) }
input go: DifferentialSpeed -> drive(linear + angular * TRACK / 2, linear - angular * TRACK / 2)
link base { mass 3  inertia [0.02, 0.02, 0.04] }
link left { collision cylinder(R, 0.02) rpy [1.5707963267948966, 0, 0]  mass 0.1  inertia [0.001, 0.001, 0.001] }
link right { collision cylinder(R, 0.02) rpy [1.5707963267948966, 0, 0]  mass 0.1  inertia [0.001, 0.001, 0.001] }
joint left_joint: continuous base -> left { at [0, TRACK / 2, R] axis [0, 1, 0] }
joint right_joint: continuous base -> right { at [0, -TRACK / 2, R] axis [0, 1, 0] }
transmission l: left_joint { command velocity to wheels.left { raw = round(velocity * R * 1000)  velocity = raw / 1000 / R } }
transmission r: right_joint { command velocity to wheels.right { raw = round(velocity * R * 1000)  velocity = raw / 1000 / R } }
"""


@pytest.mark.parametrize(("old", "new", "expected"), [
    ("", "", []),
    # the case: a right wheel whose axis is flipped spins the base in place
    ("at [0, -TRACK / 2, R] axis [0, 1, 0]", "at [0, -TRACK / 2, R] axis [0, -1, 0]",
     [("E612", "axis [0, -1, 0]", ("a forward command of 0.1 m/s to input `go` turns joint `right_joint` so that its "
       "wheel rolls backward (-0.1 m/s)"))]),
    # the same wheel turned round by its joint's frame instead (yaw of half a turn): the axis is right
    ("at [0, -TRACK / 2, R] axis [0, 1, 0]", "at [0, -TRACK / 2, R] rpy [0, 0, 3.141592653589793] axis [0, -1, 0]",
     []),
    ("drive(linear + angular * TRACK / 2, linear - angular * TRACK / 2)",
     "drive(linear - angular * TRACK / 2, linear + angular * TRACK / 2)",
     [("E612", "go", ("a counter-clockwise command of 0.5 rad/s to input `go` turns the base clockwise "
       "(-0.5021 rad/s)"))]),
    # the case: wheels larger than the conversions say; then the odometry of 0.1 m/s is short of the base's
    ("collision cylinder(R,", "collision cylinder(0.044,",
     [("E613", "go", ("a forward command of 0.1 m/s to input `go` moves the body's base at 0.1222 m/s: the conversions "
       "turn the wheels as if their radius were 0.036 m, the body's wheels are 0.044 m"))]),
    ("link right { collision cylinder(R,", "link right { collision cylinder(0.044,",
     [("E613", "go", ("a forward command of 0.1 m/s to input `go` also turns the body's base, at 0.09456 rad/s: its "
       "wheels roll at 0.1 and 0.1222 m/s"))]),
    ("linear + angular * TRACK / 2, linear - angular * TRACK / 2", "linear + angular * 0.15, linear - angular * 0.15",
     [("E613", "go", ("a counter-clockwise command of 0.5 rad/s to input `go` turns the body's base at 0.6383 rad/s: "
       "the input gives the wheels' speeds as if they were 0.3 m apart, the body's wheel joints are 0.235 m apart"))]),
])
def test_a_differential_drive_moves_as_its_input_commands(tmp_path: Path, old: str, new: str,
                                                          expected: list[Found]) -> None:
    assert old in DRIVE
    assert errors(tmp_path, DRIVE.replace(old, new)) == expected


# issue 26: the 33 samples of -1.5..1.5 are 0.09375 apart; a step between two of them (0.5625 and
# 0.65625) is found by interval arithmetic over the whole range.
BETWEEN = [
    (("command position to servo.goal { raw = round(position * 300) + 512 + (2000 if 0.6 < position and position "
      "< 0.61 else 0)  position = (raw - 512) / 300 }"),
     [("E606", ("joint `lift`'s position 0.609375 becomes 2695 at servo.goal, outside its range 0..1023, between the "
                "33 values sampled"))]),
    # bounds wider than the values (position - position): nothing outside is reported
    (("command position to servo.goal { raw = round(position * 300 + (position - position) * 1000) + 512"
      "  position = (raw - 512) / 300 }"), []),
]


@pytest.mark.parametrize(("binding", "expected"), BETWEEN)
def test_a_conversion_is_checked_between_its_samples(tmp_path: Path, binding: str, expected: list[Found]) -> None:
    assert [found[0::2] for found in errors(tmp_path, conversion(binding))] == expected
