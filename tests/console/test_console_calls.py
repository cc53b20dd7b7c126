"""What the console does with a page's call, without a browser: the form's texts typed as the
description declares them, the exact bytes written, and a refused value answered with its
error (on every page's error list) and nothing written. And its command line's usage errors."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest
from conftest import REPO, cli_env
from engine.test_one_engine import ScriptedPort

from rdisc import engine
from rdisc.console.server import Console, origins_for
from rdisc.runtime import load

DESCRIPTION = """
robot t { }
connection link: serial { baud 9600 }
primitive move(speed: int in -100..100, on: bool) on link pack "<bB" (speed, 1 if on else 0)
primitive blob(data: bytes in 0..8) on link pack "B*" (len(data), data)
primitive goals(goal: int[3] in 0..255) on link pack "3B" (goal)
primitive say(text: string) on link format "S{}\\n" (text)
interface go(speed: int in 0..7 = 5, fast: bool = False) { move(speed * 2 if fast else speed, True) }
input set_velocity: DifferentialSpeed -> go(round(linear * 7), angular > 0)
"""


@pytest.fixture
def console(tmp_path):
    path = tmp_path / "t.rdis"
    path.write_text(DESCRIPTION)
    port = ScriptedPort()
    robot = load(path).connect(port, threads=False)
    events: list[dict] = []
    console = Console(robot, "<p>page</p>")
    console._push = events.append  # what every page would be sent
    yield console, port, events
    robot.close()


def call(console: Console, kind: str, name: str, **values: object) -> dict:
    return console.call(json.dumps({"id": 1, "kind": kind, "name": name, "values": values}))


@pytest.mark.parametrize(("kind", "name", "values", "written"), [
    ("primitive", "move", {"speed": "-3", "on": True}, b"\xfd\x01"),
    ("primitive", "move", {"speed": "0x10", "on": False}, b"\x10\x00"),
    ("primitive", "blob", {"data": "0a0b"}, b"\x02\x0a\x0b"),
    ("primitive", "goals", {"goal": "[1, 2, 255]"}, b"\x01\x02\xff"),
    ("primitive", "goals", {"goal": "4, 5, 6"}, b"\x04\x05\x06"),
    ("primitive", "say", {"text": " hi "}, b"S hi \n"),
    ("interface", "go", {"speed": "", "fast": False}, b"\x05\x01"),  # empty: the default
    ("interface", "go", {"speed": "3", "fast": True}, b"\x06\x01"),
    ("input", "set_velocity", {"linear": "1", "angular": "-0.5"}, b"\x07\x01"),
])
def test_a_call_is_typed_as_declared_and_written(console, kind, name, values, written) -> None:
    robot_console, port, _ = console
    assert call(robot_console, kind, name, **values) == {"type": "result", "id": 1, "ok": True}
    assert bytes(port.written) == written


@pytest.mark.parametrize(("kind", "name", "values", "error", "message"), [
    ("primitive", "move", {"speed": "1.5", "on": True}, "ValueError", "move: speed must be an int, not '1.5'"),
    ("primitive", "move", {"speed": "200", "on": True}, "RdisValueError",
     "move: parameter speed is 200, outside -100..100"),
    ("primitive", "move", {"speed": "1", "on": "yes"}, "ValueError", "move: on must be true or false, not 'yes'"),
    ("primitive", "move", {"speed": "1"}, "TypeError", "move: on is missing"),
    ("primitive", "move", {"speed": "1", "on": True, "x": "1"}, "TypeError",
     "move has no parameter or field named 'x'"),
    ("primitive", "move", {"speed": 1, "on": True}, "TypeError", "move: speed is given as text, not int"),
    ("input", "set_velocity", {"linear": "fast", "angular": "0"}, "ValueError",
     "set_velocity: linear must be a number, not 'fast'"),
    ("input", "nothing", {}, "KeyError", "t has no input named 'nothing'"),
    ("output", "set_velocity", {}, "ValueError",
     "a call is of an input, an interface or a primitive, not 'output'"),
])
def test_a_refused_call_writes_nothing_and_is_an_error_on_the_page(console, kind, name, values, error,
                                                                    message) -> None:
    robot_console, port, events = console
    assert call(robot_console, kind, name, **values) == {"type": "result", "id": 1, "ok": False, "error": error,
                                                         "message": message}
    assert bytes(port.written) == b""
    assert [(e["error"], e["message"]) for e in events if e["type"] == "error"] == [(error, message)]


def test_a_call_that_is_not_a_call_is_refused(console) -> None:
    robot_console, port, _ = console
    for text in ("[1]", "not json", json.dumps({"id": 2, "kind": "input", "name": 3})):
        assert robot_console.call(text)["ok"] is False
    assert bytes(port.written) == b""


def test_the_origins_are_the_consoles_own() -> None:
    assert origins_for("127.0.0.1", 8765) == {"http://127.0.0.1:8765", "http://localhost:8765",
                                              "http://[::1]:8765"}
    assert "http://192.168.1.5:80" in origins_for("192.168.1.5", 80)
    assert origins_for("0.0.0.0", 80, ["http://robot.lan:80/"]) == origins_for("127.0.0.1", 80) | {
        "http://robot.lan:80"}


@pytest.mark.parametrize(("args", "status", "message"), [
    (["--port", "loop://", "--http", "nowhere"], 2, "rdisc console: --http `nowhere` is not HOST:PORT"),
    (["--port", "loop://", "--set", "X=1"], 2,
     "rdisc console: irobot_create: no setting named 'X' (its settings: none)"),
    (["--sim", "--port", "loop://"], 2,
     "rdisc console: --sim drives a simulation in place of the device: give --port or --sim, not both"),
    (["--port", "loop://", "--seed", "3"], 2, "rdisc console: --seed is for --sim"),
    (["--sim", "--http", "127.0.0.1:0"], 2,
     "rdisc console: examples/create.rdis has no body to simulate: it declares no `link`"),
    (["--port", "/dev/rdisc-no-such-port", "--http", "127.0.0.1:0"], 1,
     "rdisc console: RdisConnectionError: btserial: cannot open /dev/rdisc-no-such-port"),
])
def test_usage_and_connection_errors(args, status, message) -> None:
    done = subprocess.run([sys.executable, "-m", "rdisc", "console", "examples/create.rdis", *args], cwd=REPO,
                          env=cli_env(), capture_output=True, text=True, timeout=120, check=False)
    assert done.returncode == status, done.stderr
    assert message in done.stderr
    assert "Traceback" not in done.stderr


def test_the_body_message_is_the_simulated_links_frames_and_joints_positions() -> None:
    """`--sim`'s pushed message: the example arm straight up, each link's origin (m) and
    orientation (w, x, y, z), each moving joint's position."""
    pytest.importorskip("mujoco")
    from rdisc.compile import compile_path
    from rdisc.sim import Simulation

    arm = REPO / "examples" / "arm.rdis"
    model = compile_path(str(arm)).model
    assert model is not None
    sim = Simulation(model)
    robot = load(arm).connect(sim=sim, threads=False)
    try:
        event = Console(robot, "<p>page</p>", body=sim)._body_event(sim)
    finally:
        robot.close()
    assert isinstance(event.pop("t"), float)
    unturned = [1.0, 0.0, 0.0, 0.0]
    heights = {"base": 0.0, "turret": 0.045, "upper_arm": 0.095, "forearm": 0.295, "wrist": 0.475, "hand": 0.525}
    assert json.loads(json.dumps(event)) == {
        "type": "body",
        "links": {**{link: [0.0, 0.0, z, *unturned] for link, z in heights.items()},
                  "jaw": [0.0, 0.02, 0.585, *unturned]},
        "joints": dict.fromkeys(["waist", "shoulder", "elbow", "wrist_pitch", "wrist_roll", "gripper"], 0.0),
    }


class _Answers:
    """A device that answers every write with the same bytes."""

    def __init__(self, answer: bytes) -> None:
        self.answer_bytes = answer

    def answer(self, request: bytes) -> bytes:
        return self.answer_bytes

    def listen(self) -> bytes:
        return b""


def test_a_raw_send_writes_the_typed_bytes_and_answers_with_the_device_s(console) -> None:
    robot_console, port, events = console
    port.device = _Answers(b"\x3a\x98OK\n")
    sent = robot_console.call(json.dumps({"id": 4, "kind": "raw", "connection": "link", "hex": "8E 16, 0x41 42"}))
    assert sent == {"type": "result", "id": 4, "ok": True, "sent": "8e 16 41 42", "sent_text": "..AB",
                    "answer": "3a 98 4f 4b 0a", "text": ":.OK."}
    assert port.writes == [b"\x8e\x16\x41\x42"]
    assert [(e["direction"], e["data"]) for e in events if e["type"] == "io"] == [
        ("write", "8e 16 41 42"), ("read", "3a 98 4f 4b 0a")]
    # the only connection need not be named; no answer is an empty one
    port.device = None
    assert robot_console.call(json.dumps({"id": 5, "kind": "raw", "hex": "01"}))["answer"] == ""


@pytest.mark.parametrize(("given", "error", "message"), [
    ("8e zz", "ValueError", "raw: 'z' is not a hex digit (type the bytes as hex: 8e 16)"),
    ("8e 1", "ValueError", "raw: 3 hex digits are not whole bytes (two digits a byte: 0e, not e)"),
    ("  ", "ValueError", "raw: no bytes given (type them as hex: 8e 16)"),
    ("0x", "ValueError", "raw: no bytes given (type them as hex: 8e 16)"),
    ("٣٣", "ValueError", "raw: '٣' is not a hex digit (type the bytes as hex: 8e 16)"),
    ("00" * 4097, "ValueError", "raw: 4097 bytes; a raw send writes at most 4096"),
    (7, "TypeError", "raw: the bytes are given as hex text"),
])
def test_bad_hex_is_a_message_and_nothing_is_written(console, given, error, message) -> None:
    robot_console, port, events = console
    assert robot_console.call(json.dumps({"id": 6, "kind": "raw", "connection": "link", "hex": given})) == {
        "type": "result", "id": 6, "ok": False, "error": error, "message": message}
    assert bytes(port.written) == b""
    assert [(e["error"], e["message"]) for e in events if e["type"] == "error"] == [(error, message)]


def test_a_raw_send_on_no_such_connection_is_refused(console) -> None:
    robot_console, port, _ = console
    assert robot_console.call(json.dumps({"id": 8, "kind": "raw", "connection": "elsewhere", "hex": "01"})) == {
        "type": "result", "id": 8, "ok": False, "error": "KeyError", "message": "t has no connection named 'elsewhere'"}
    assert bytes(port.written) == b""


SENSED = """
robot s { }
connection link: serial { baud 9600 }
primitive heat() on link pack "B" (7) unpack "b"
sensor temperature: int from heat() cache 100 ms
primitive leds(level: int in 0..255) on link pack "BB" (139, level)
interface show() { leds(temperature) }
"""


def test_the_state_event_says_how_old_each_sensor_is(tmp_path) -> None:
    """A sensor's age by the robot's clock in the state pushed to the pages (null before its
    first read); the state is pushed again when the sensor is read anew, not while it is kept."""
    path = tmp_path / "s.rdis"
    path.write_text(SENSED)
    port = ScriptedPort(b"\x21\x22")
    robot = load(path).connect(port, threads=False)
    now = [10.0]
    robot._clock = lambda: now[0]
    events: list[dict] = []
    console = Console(robot, "<p>page</p>")
    console._push = events.append
    try:
        assert console._sensor_ages() == {"temperature": None}  # as a new page's hello says
        assert call(console, "interface", "show") == {"type": "result", "id": 1, "ok": True}
        assert bytes(port.written) == b"\x07\x8b\x21"
        assert [e for e in events if e["type"] == "state"][-1] == {
            "type": "state", "state": {"temperature": 33}, "sensor_ages": {"temperature": 0.0}}
        now[0] = 10.05  # kept: nothing read, and no new state to push
        pushed = len(events)
        assert call(console, "interface", "show") == {"type": "result", "id": 1, "ok": True}
        assert bytes(port.written) == b"\x07\x8b\x21\x8b\x21"
        assert [e for e in events[pushed:] if e["type"] == "state"] == []
        now[0] = 10.25  # stale: read anew, and its age starts again
        assert call(console, "interface", "show") == {"type": "result", "id": 1, "ok": True}
        assert bytes(port.written) == b"\x07\x8b\x21\x8b\x21\x07\x8b\x22"
        assert [e for e in events if e["type"] == "state"][-1] == {
            "type": "state", "state": {"temperature": 34}, "sensor_ages": {"temperature": 0.0}}
    finally:
        robot.close()


def test_the_stop_of_the_last_page_closing_is_told_while_the_console_holds_the_ports(tmp_path) -> None:
    """When the last page closes, the terminate hook's call is told to the session and written
    with every port held, as a page's calls are: a tick of a `threading single` connection cannot
    write between the two, so a recording's order of runs is the wire's (what `rdisc replay` follows)."""
    path = tmp_path / "t.rdis"
    path.write_text(DESCRIPTION.replace("connection link: serial { baud 9600 }",
                                        "connection link: serial { baud 9600\n    terminate go(0, False) }"))
    port = ScriptedPort()
    robot = load(path).connect(port, threads=False)
    try:
        session = engine.Session(robot)
        console = Console(robot, "<p>page</p>", session=session)
        held: list[tuple[str, bool]] = []
        told = session.call

        def call(kind: str, name: str, values: dict) -> None:
            held.extend((connection, opened.lock._is_owned()) for connection, opened in robot._ports.items())
            told(kind, name, values)

        session.call = call  # type: ignore[method-assign]
        console._last_page_closed()
        assert held == [("link", True)]
        assert bytes(port.written) == b"\x00\x01"
    finally:
        robot.close()


@pytest.mark.parametrize("text", [
    '{"id": NaN, "kind": "interface", "name": "go", "values": {}}',
    '{"id": 1, "kind": "interface", "name": "go", "values": {"speed": Infinity}}',
    '{"id": 1e999, "kind": "raw", "hex": "00"}',
    '{"id": -Infinity, "kind": "raw", "hex": "00"}',
])
def test_a_number_json_cannot_hold_is_refused_and_the_answer_is_json(console, text) -> None:
    """Python's JSON reader takes NaN, Infinity and 1e999 (as inf); echoed as the call's id they
    made an answer no page can read (`JSON.parse` refuses NaN)."""
    robot_console, port, _ = console
    answer = robot_console.call(text)
    word = next(w for w in ("NaN", "-Infinity", "Infinity", "1e999") if w in text)
    assert answer == {"type": "result", "id": None, "ok": False, "error": "ValueError",
                      "message": f"a call's numbers are finite: {word} is not"}
    json.dumps(answer, allow_nan=False)
    assert bytes(port.written) == b""
