"""The runtime and the generated driver agree on random descriptions, not only random inputs.

tests/test_one_semantics.py drives both implementations of a few fixed
descriptions; here hypothesis draws the descriptions too (tests/properties/
descriptions.py): frames with every kind of part (two length fields too), stuffing, reply tables and
tagged replies, acknowledgements, listeners, `skip unmatched`, ASCII formats and
regexes, ranges, bytes, a reply for each element of an array parameter (`replies
eid in ids`), reply timeouts, post-actions, interfaces, hooks, inputs
and outputs. Each is compiled, loaded by the runtime and imported as a generated
driver, then both run the same sessions against a device that answers validly or
not (tests/properties/differential_support.py). Bytes written, input resets,
state, outputs, errors and I/O events must be the same; and, since both could
break a rule alike, each must keep the contract where a comparison cannot tell:
every byte read shown to on_io, a valid reply decoded, only the contract's error
types raised. An open bug both share can be listed in `differential_support.KNOWN`
(with an xfail test of its own) for the random tests to pass over it until it is fixed.

A second test renames each description's names to the engine's (tests/properties/renaming.py):
a driver must take none of them from its engine.

Only the public API is used, so the tests hold across rewrites of the internals.
The example count is modest; `python benchmarks/differential.py --descriptions
2000` searches much longer and lists every problem it finds.
"""

from __future__ import annotations

import dataclasses
import re
from pathlib import Path
from typing import Any

import pytest
from conftest import fuzz_examples
from descriptions import (
    CATALOGUE,
    INT,
    STRING,
    Connection,
    Decoding,
    Description,
    Frame,
    Interface,
    Lit,
    Name,
    Operation,
    Part,
    Primitive,
    Reply,
    ReplyPlan,
    Script,
    Sensor,
    _own_rate,
    constructs,
    crc,
    descriptions,
    frames,
    looked_up,
    scripts,
)
from differential_support import Clock, Pair, Pairs, compare, normal
from hypothesis import HealthCheck, Phase, find, given, settings
from hypothesis import strategies as st
from hypothesis.errors import NoSuchExample
from renaming import engine_names, renamed, renamings

from rdisc.compile import compile_path
from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

SESSIONS = 3  # scripts per description: a driver costs an import, a session microseconds


@pytest.fixture(scope="module")
def pairs(tmp_path_factory: pytest.TempPathFactory) -> Pairs:
    return Pairs(str(tmp_path_factory.mktemp("differential")))


@settings(max_examples=fuzz_examples(30), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                                 HealthCheck.data_too_large])
@given(data=st.data())
def test_runtime_and_generated_driver_agree_on_random_descriptions(pairs: Pairs, data: st.DataObject) -> None:
    description: Description = data.draw(descriptions(), label="description")
    pair = pairs(description)
    for session in range(SESSIONS):
        script = data.draw(scripts(description), label=f"session {session}")
        outcome = compare(pair, script)
        assert outcome.ok, outcome.report()


@settings(max_examples=fuzz_examples(15), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow,
                                 HealthCheck.data_too_large])
@given(data=st.data())
def test_they_agree_where_the_names_are_the_engines(tmp_path: Path, data: st.DataObject) -> None:
    """The same, with the description's names the engine's (`lookup`, `Robot`, `lane`, `open`):
    a driver takes none of them from its engine, so it still does what the runtime does."""
    drawn: Description = data.draw(descriptions(), label="description")
    renaming = data.draw(renamings(drawn.text), label="renaming")
    description = dataclasses.replace(drawn, text=renamed(drawn.text, renaming))
    pair = Pair(description, str(tmp_path), renaming)
    try:
        for session in range(SESSIONS):
            script = data.draw(scripts(drawn), label=f"session {session}")
            outcome = compare(pair, script)
            assert outcome.ok, outcome.report()
    finally:
        pair.forget()


def test_the_engines_names_are_tried_as_every_kind_of_name() -> None:
    """The pool holds the names that matter: the engine's classes, functions and modules, a typed
    method's own, the robot's methods; and each can name anything (the checker took it)."""
    assert {"Incoming", "Robot", "Frame", "Port", "lookup", "struct", "lane", "acquire", "request",
            "open", "tick", "run_for", "call_primitive"} <= set(engine_names())
    renaming = {"p0": "open", "a0": "struct", "s1": "lane"}
    assert renamed('primitive p0(a0: int) on c0 format "p0 {}" (a0) { s1 = a0 } # s1', renaming) == \
        'primitive open(struct: int) on c0 format "p0 {}" (struct) { lane = struct } # lane'


@settings(max_examples=fuzz_examples(30), deadline=None, derandomize=True, database=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(description=descriptions())
def test_every_generated_description_compiles(tmp_path: Path, description: Description) -> None:
    """The strategy builds valid descriptions, so no example is spent on a rejected one."""
    path = tmp_path / "generated.rdis"
    path.write_text(description.text, encoding="utf-8")
    errors = [f"{d.code} {d.message}" for d in compile_path(str(path)).diagnostics.items if d.severity.name == "ERROR"]
    assert not errors, f"\n{description.text}\n{errors}"


QUICK = settings(max_examples=500, database=None, derandomize=True, phases=[Phase.generate],
                suppress_health_check=list(HealthCheck))


def test_the_strategies_draw_layouts_a_setting_chooses() -> None:
    """Frames whose request or reply layout MODE chooses (`either when`), the chosen one first or not:
    the differential search holds runtime and driver to the same choice (`constructs` counts them)."""
    seen: dict[tuple[str, bool], Frame] = {}

    def complete(frame: Frame) -> bool:
        for side in ("request", "reply"):
            if getattr(frame, f"other_{side}"):
                seen.setdefault((side, frame.holds), frame)
        return {side for side, _ in seen} == {"request", "reply"} and {holds for _, holds in seen} == {True, False}

    find(frames("f0"), complete, settings=QUICK)
    for (side, holds), frame in seen.items():
        chosen, other = getattr(frame, side), getattr(frame, f"other_{side}")
        assert frame.params[-1] == "qm" and re.fullmatch(r"qm (==|!=) [0-3]", frame.when)
        assert (frame.when in ("qm == 1", "qm != 0", "qm != 2", "qm != 3")) == holds  # MODE is 1
        assert other[0].kind == "header" and other[0].data != (chosen[0].data if chosen[0].kind == "header" else b"")
        first, second = (chosen, other) if holds else (other, chosen)
        text = frame.text()
        assert f"{side} {{ either when {frame.when} {{ {first[0].text()}" in text
        assert f" }} or {{ {second[0].text()}" in text


def test_the_strategies_draw_lookups_in_framed_replies() -> None:
    """A framed reply of a fixed size, one more byte looked up in LOOK by a post-action: the device model
    calls a reply whose byte LOOK lacks invalid (a lookup miss: a protocol error, read past under `skip
    unmatched`)."""
    reply = Reply(Decoding("unpack", "<H", (INT, ), 2), (("s0", Name(INT, "s0")),))
    frame = Frame("f0", (), (Part("payload"),), (Part("header", b"\x02"), Part("length", fmt="B"), Part("payload")),
                  False)

    @st.composite
    def looked(draw: st.DrawFn) -> Reply | None:
        return looked_up(draw, reply, frame, {"s0": INT, "s1": STRING})

    made = find(looked(), lambda made: made is not None, settings=QUICK)
    assert made is not None and made.decoding == Decoding("unpack", "<HB", (INT, INT), 3)
    assert [(target, e.text()) for target, e in made.actions] == [("s0", "LOOK[out[1]]")]


@pytest.mark.parametrize("name, check", [
    ("crc8", 0xF4), ("crc8-maxim", 0xA1), ("crc8-dvb-s2", 0xBC), ("crc16-xmodem", 0x31C3),
    ("crc16-ccitt-false", 0x29B1), ("crc16-kermit", 0x2189), ("crc16-modbus", 0x4B37), ("crc16-arc", 0xBB3D),
    ("crc16-x25", 0x906E), ("crc32", 0xCBF43926), ("crc32c", 0xE3069283),
])
def test_the_device_model_computes_the_catalogue_check_values(name: str, check: int) -> None:
    """Replies the device model calls valid carry right CRCs (the catalogue's check of "123456789")."""
    assert crc(b"123456789", *CATALOGUE[name]) == check


# ---- fixed cases: the four former disagreements, and four faults both shared that this test found --------


HEADER = """robot cases { author "tests" }
state v: int = 0
connection link: serial { baud 9600 }
frame summed(id: int) { header "\\xFF\\xFF"  field id "B" = id  length "B" = payload + 1  payload  checksum "sum" "B" inverted }
"""


@pytest.fixture(params=["runtime", "driver"])
def robot_of(request: pytest.FixtureRequest, tmp_path: Path) -> Any:
    """robot_of(description, port) -> (robot, its on_io events) for one implementation."""
    def make(text: str, port: ScriptedPort) -> tuple[Any, list[tuple[Any, ...]]]:
        path = tmp_path / "case.rdis"
        path.write_text(HEADER + text, encoding="utf-8")
        events: list[tuple[Any, ...]] = []
        callbacks = {"threads": False, "on_io": lambda *event: events.append(event)}
        if request.param == "runtime":
            return load(path).connect(port, **callbacks), events
        name = "case_" + re.sub(r"\W", "_", request.node.name)
        return import_driver(path, tmp_path, name).connect(port, **callbacks), events
    return make


READ = 'primitive p() on link frame summed(1) pack "B" (4) unpack "B" { v = out[0] }\n'


def _frame(ident: int, payload: bytes) -> bytes:
    body = bytes([ident, len(payload) + 1]) + payload
    return b"\xff\xff" + body + bytes([~sum(body) & 0xFF])


def test_a_reply_field_named_like_a_request_field_is_checked_against_its_own_value(robot_of) -> None:
    """Formerly refused ('reply a is 144, expected 129'): seen here by the valid-reply check."""
    text = ('frame named { request { field a "B" = 0x81  payload } reply { field a "B" = 0x90  payload } }\n'
            'primitive p() on link frame named pack "B" (1) unpack "B" { v = out[0] }\n')
    robot, _ = robot_of(text, ScriptedPort(b"\x90\x07"))
    robot.call_primitive("p")
    assert robot.state["v"] == 7


def test_a_tagged_reply_through_a_frame_ended_by_a_terminator_decodes(robot_of) -> None:
    """Formerly a disagreement: the runtime failed, the driver decoded."""
    text = ('frame ended { request { payload } reply { payload  terminator "\\xFF" } }\n'
            'primitive p() on link frame ended pack "B" (2) reply tag "B" {\n'
            '    0x10: unpack "B" { v = out[0] }  0x11: unpack "<H" { v = out[0] } }\n')
    robot, _ = robot_of(text, ScriptedPort(b"\x11\x34\x12\xff"))
    robot.call_primitive("p")
    assert robot.state["v"] == 0x1234


def test_skip_unmatched_reads_past_frames_an_unpack_primitive_does_not_match(robot_of) -> None:
    """Formerly a disagreement: the runtime skipped, the driver raised RdisProtocolError."""
    text = 'primitive p() on link frame summed(1) pack "B" (3) skip unmatched timeout 50 ms unpack "B" { v = out[0] }\n'
    robot, _ = robot_of(text, ScriptedPort(_frame(2, b"\x05") + _frame(1, b"\x09")))
    robot.call_primitive("p")
    assert robot.state["v"] == 9


def test_a_framed_reply_that_fails_is_shown_to_on_io(robot_of) -> None:
    """Formerly shown by neither: seen here by the on_io check."""
    spoilt = _frame(1, b"\x05")[:-1] + b"\x00"
    robot, events = robot_of(READ, ScriptedPort(spoilt))
    with pytest.raises(Exception, match="^p: ") as raised:
        robot.call_primitive("p")
    assert type(raised.value).__name__ == "RdisProtocolError"
    assert b"".join(data for direction, _, data in events if direction == "read") == spoilt


def test_a_float_too_large_for_its_pack_code_is_an_rdis_value_error(robot_of) -> None:
    """Found by the differential test: an OverflowError from struct escaped."""
    robot, _ = robot_of('primitive p(x: float) on link pack "<e" (x)\n', ScriptedPort(b""))
    with pytest.raises(Exception, match="^p: ") as raised:
        robot.call_primitive("p", 1e300)
    assert type(raised.value).__name__ == "RdisValueError"


def test_an_xor_narrower_than_a_byte_is_reduced_to_its_width(robot_of) -> None:
    """Found by the differential test: a 4-bit XOR was written as two hex digits, a 1-bit one compared whole."""
    text = ('frame nibble { header "$"  payload  literal "*"  checksum "xor" hex width 4 }\n'
            'primitive p() on link frame nibble pack "BB" (0x31, 0x60) unpack "B" { v = out[0] }\n')
    port = ScriptedPort(b"$A*" + b"%X" % ((0x41 ^ 0x2A) & 0xF))
    robot, _ = robot_of(text, port)
    robot.call_primitive("p")
    assert bytes(port.written) == b"$1`*" + b"%X" % ((0x31 ^ 0x60 ^ 0x2A) & 0xF)
    assert robot.state["v"] == 0x41


def test_a_write_the_port_refuses_shows_no_stale_reply_to_on_io(robot_of) -> None:
    """Found by the differential test: the failed exchange showed the bytes of the one before it."""
    port = ScriptedPort(_frame(1, b"\x05"))
    robot, events = robot_of(READ, port)
    robot.call_primitive("p")
    port.fail = True
    with pytest.raises(Exception, match="^link: ") as raised:
        robot.call_primitive("p")
    assert type(raised.value).__name__ == "RdisConnectionError"
    assert [e for e in events if e[0] == "read"] == [("read", "link", _frame(1, b"\x05"))]


def test_a_stuffed_reply_ended_by_a_constant_is_read_up_to_the_constant(robot_of) -> None:
    """Found by the differential test: the decoding's size was read, which stuffing had made longer."""
    text = ('frame stuffed { stuff "\\x00" after "\\xFF"  header "\\xAA"  payload  terminator "\\x55" }\n'
            'primitive p() on link frame stuffed pack "B" (1) unpack ">H" { v = out[0] }\n')
    robot, _ = robot_of(text, ScriptedPort(b"\xaa\xff\x00\x01\x55"))  # the payload FF 01, stuffed
    robot.call_primitive("p")
    assert robot.state["v"] == 0xFF01


def test_a_sensor_keeps_its_value_in_the_driver_as_in_the_runtime(robot_of) -> None:
    """Found by the differential test over sensors: the driver's post-actions that set most of the state
    gave the whole new state (`renews`) without the sensors, so a sensor's read stored nothing
    (`robot.sensors.r` a KeyError) and another primitive's reply dropped the value read."""
    text = ('primitive level() on link pack "B" (4) unpack "B"\n'
            'sensor r: int from level() cache 100 ms\n'
            'primitive set_v() on link pack "B" (5) unpack "B" { v = out[0] }\n')
    port = ScriptedPort(b"\x07\x09")
    robot, _ = robot_of(text, port)
    assert robot.sensors.r == 7
    robot.call_primitive("set_v")
    assert dict(robot.state) == {"v": 9, "r": 7}
    assert bytes(port.written) == b"\x04\x05"


@pytest.mark.parametrize("construct, written", [
    ("sensor", r"\nsensor r0: \w+ from p\d+\(\) cache \d+ ms"),
    ("threading dual or multiple", r"threading (dual|multiple) at 50 Hz"),
    ("noise", r" noise "),
    ("actuator", r"\nactuator m0: (servo|wheel) \{ velocity [\d.]+.*\ntransmission t0: j0 actuator m0 \{\n    command "),
    ("kalman filter", r" filter \w+ kalman \{ state .+  transition .+  process .+  measurement .+  noise "),
])
def test_the_strategies_draw_chapter_7_constructs(construct: str, written: str) -> None:
    """Sensors (read by outputs, interfaces and inputs), threading models, noise, Kalman filters and
    actuators (thesis ch. 7): the differential search holds runtime and driver to the same reads, cache
    ages, estimates and commands (`constructs` counts them)."""
    found = find(descriptions(), lambda d: construct in constructs(d), settings=QUICK)
    assert re.search(written, found.text), found.text


def test_a_periodic_interface_under_threading_multiple_is_drawn_a_rate_of_its_own() -> None:
    """`periodic N Hz` (its own thread's rate), on a `threading multiple` connection only."""
    periodic = Interface("i0", (), (), periodic=True)

    @st.composite
    def rated(draw: st.DrawFn, threading: str) -> Interface:
        return _own_rate(draw, periodic, {"c0": threading}, ("c0",))

    found = find(rated("multiple"), lambda i: i.rate is not None, settings=QUICK)
    assert re.fullmatch(r"interface i0\(\) periodic (2|20|100) Hz \{\n\n\}", found.text())
    with pytest.raises(NoSuchExample):
        find(rated("dual"), lambda i: i.rate is not None, settings=QUICK)


def test_a_sensor_read_within_its_cache_time_is_seen_by_the_device_model(pairs: Pairs) -> None:
    """The harness's device answers a sensor's read only when the robot makes it: twice read within
    the cache time is one exchange, after a wait of the cache time another (the clock the wire's)."""
    sensed = Primitive("p0", (), "c0", "pack", "B", (Lit(INT, 0x41),),
                       Reply(Decoding("unpack", "<H", (INT,), 2)))
    sensor = Sensor("r0", INT, sensed, 50)
    base = Description((("s0", INT, 0),), (), (), (Connection("c0"),), (sensed,), (), (), (), (sensor,))
    description = dataclasses.replace(base, text=base.render())
    valid = ReplyPlan("valid", b"\x01\x02")
    ops = (Operation("sensor", "r0", plans=(valid,)), Operation("sensor", "r0", plans=(valid,)),
           Operation("wait", args=(60,)), Operation("sensor", "r0", plans=(ReplyPlan("valid", b"\x03\x04"),)))
    outcome = compare(pairs(description), Script((), ops, ()))
    assert outcome.ok, outcome.report()
    log = outcome.runtime.log
    assert [entry[1] for entry in log if entry[0] == "write"] == [b"\x41", b"\x41"]
    reads = [entry[2] for entry in log if entry[0] == "sensors.r0"]
    assert reads == [0x0201, 0x0201, 0x0403]
    ages = [entry[3][1][0][1] for entry in log if entry[0] in ("sensors.r0", "wait(60 ms)")]
    assert ages == [normal(0.0), normal(0.0), normal((Clock().now + 0.06) - Clock().now), normal(0.0)]


def test_a_terminate_hook_reads_a_sensor(robot_of) -> None:
    """Found beside the differential test over sensors (both implementations alike, so no disagreement):
    a terminate hook whose interface read a stale sensor was refused, 'closed', and wrote nothing; it
    reads it, as the hook's own commands are written, and its command is the last written."""
    text = ('connection arm: serial { baud 9600  terminate park() }\n'
            'primitive level() on arm pack "B" (4) unpack "B"\n'
            'sensor height: int from level() cache 100 ms\n'
            'primitive show(value: int) on arm pack "BB" (2, value)\n'
            'interface park() { show(height) }\n')
    port = ScriptedPort(b"\x07")
    robot, _ = robot_of(text, port)
    errors: list[BaseException] = []
    robot.on_error(errors.append)
    robot.close()
    assert (bytes(port.written), errors) == (b"\x04\x02\x07", [])
