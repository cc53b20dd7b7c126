"""Sensors (thesis §7.2.4) in the runtime and a generated driver alike: a value read through its
primitive is kept for the cache time, readers share one read, a failed read raises.

examples/create.rdis reads its bumpers as a sensor kept for 100 ms while its output is published
at 40 Hz. The robot's clock is injected (`robot._clock`, the schedule's time), so the counts below
do not depend on how fast the machine is: requests are counted on a pseudo-terminal.
"""

from __future__ import annotations

import importlib.util
import json
import sys
import threading
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import Any

import pytest
from devices import pty_device
from runtime_support import CREATE, Recorder

from rdisc import engine
from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from rdisc.runtime import load

BUMPERS = bytes([142, 7])  # OI Sensors, packet 7


def _driver_robot(folder: Path) -> Callable[..., engine.Robot]:
    """The generated Create driver's robot class, imported from a file."""
    compilation = compile_path(str(CREATE))
    assert compilation.model is not None
    path = folder / "create_sensor_driver.py"
    path.write_text(to_python(compilation.model, "create.rdis"), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"create_sensor_driver_{abs(hash(str(path)))}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    made: Callable[..., engine.Robot] = module.IrobotCreate
    return made


@pytest.fixture(params=["runtime", "driver"])
def make_robot(request: pytest.FixtureRequest, tmp_path: Path) -> Callable[..., engine.Robot]:
    """A function making a Create robot, not opened: the runtime's, or the generated driver's."""
    if request.param == "runtime":
        device = load(CREATE).device
        return lambda timeout=1.0: engine.Robot(device, timeout=timeout)
    return _driver_robot(tmp_path)


class Clock:
    """The robot's clock, moved by the test."""

    def __init__(self) -> None:
        self.now = 64.0

    def __call__(self) -> float:
        return self.now


def _opened(robot: engine.Robot, port: str, clock: Clock) -> engine.Robot:
    """The robot on `port`, its delays not waited for, its clock the test's, no thread running."""
    robot._clock = clock
    robot._sleep = lambda seconds: None
    robot.open(port, threads=False)
    return robot


def _answering(bumpers: int, answers: list[bool] | None = None) -> Callable[[bytes], bytes | None]:
    """The Create's answer to a bumpers request; while `answers[0]` is False, none."""
    def handle(data: bytes) -> bytes | None:
        if data.endswith(BUMPERS) and (answers is None or answers[0]):
            return bytes([bumpers])
        return None
    return handle


def _requests(received: bytes) -> int:
    return received.count(BUMPERS)


@pytest.fixture
def device() -> Iterator[Any]:
    with pty_device(_answering(0b01)) as dev:
        yield dev


def test_the_output_at_40_hz_reads_the_bumpers_once_per_100_ms(make_robot, device) -> None:
    clock = Clock()
    outputs = Recorder()
    robot = make_robot()
    robot.on_output(outputs)
    _opened(robot, device.port, clock)
    try:
        for _ in range(40):  # one second of ticks, 25 ms apart
            robot.tick()
            clock.now += 0.025
        assert len(outputs) == 40  # every tick publishes
        assert {o["contents"]["distance"] for o in outputs.snapshot()} == {0.0}  # the right bumper, pressed
    finally:
        robot.close()
    # the startup's Start and Full, then ten reads of the bumpers (one per 100 ms), and the terminate's Drive
    device.wait_for(2 + 10 * 2 + 5, timeout=5.0)
    assert device.received[:2] == bytes([128, 132])
    assert _requests(device.received) == 10
    assert device.received[2:].replace(BUMPERS, b"") == bytes([137, 0, 0, 0, 0])


def test_a_reader_within_the_cache_time_sends_nothing(make_robot, device) -> None:
    clock = Clock()
    robot = _opened(make_robot(), device.port, clock)
    try:
        assert robot.sensors.bumperStates == 0b01
        assert robot.sensor_age("bumperStates") == 0.0
        clock.now += 0.0625
        assert robot.sensors.bumperStates == 0b01
        assert robot.sensor_age("bumperStates") == 0.0625
        assert _requests(device.received) == 1
        clock.now += 0.0625  # 125 ms after the read: stale, read again
        assert robot.sensors.bumperStates == 0b01
        assert robot.sensor_age("bumperStates") == 0.0
        assert _requests(device.received) == 2
        assert "bumperStates" in dir(robot.sensors)
        with pytest.raises(AttributeError, match="no sensor named 'bumpers'"):
            robot.sensors.bumpers  # noqa: B018
    finally:
        robot.close()


def test_concurrent_readers_share_one_read(make_robot) -> None:
    """Eight threads read the bumpers at once from a device that answers late: one request is
    written, and every reader gets its value (without sharing, each made its own exchange)."""
    with pty_device(_answering(0b10)) as dev:
        dev.reply_delay = 0.2
        clock = Clock()  # still: a value read is fresh for every reader after it
        robot = _opened(make_robot(), dev.port, clock)
        try:
            start = threading.Barrier(8)
            values: list[object] = []

            def read() -> None:
                start.wait()
                values.append(robot.sensors.bumperStates)

            threads = [threading.Thread(target=read) for _ in range(8)]
            for thread in threads:
                thread.start()
            for thread in threads:
                thread.join(timeout=10)
            assert values == [0b10] * 8
            assert _requests(dev.received) == 1
        finally:
            robot.close()


def test_a_failed_read_raises_and_never_serves_the_old_value(make_robot) -> None:
    answers = [True]
    with pty_device(_answering(0b11, answers)) as dev:
        clock = Clock()
        robot = _opened(make_robot(timeout=0.1), dev.port, clock)
        try:
            assert robot.sensors.bumperStates == 0b11
            clock.now += 0.125  # the value is stale, and the device stops answering
            answers[0] = False
            with pytest.raises(Exception, match="bumpers") as raised:
                robot.sensors.bumperStates  # noqa: B018
            assert raised.type.__name__ == "RdisTimeout"
            errors = Recorder()
            robot.on_error(errors)
            outputs = Recorder()
            robot.on_output(outputs)
            robot.tick()  # the periodic output reads it too: the error is reported, nothing published
            assert len(outputs) == 0
            assert [type(e).__name__ for e in errors.snapshot()] == ["RdisTimeout"]
            answers[0] = True  # the next reader tries again
            assert robot.sensors.bumperStates == 0b11
            assert _requests(dev.received) == 4
        finally:
            robot.close()


BUMPING = """\
robot bumping { author "tests" }
connection oi: serial { baud 57600  threading single at 40 Hz }
primitive bumpers() on oi pack "BB" (142, 7) unpack "B"
sensor bumps: int from bumpers() cache 100 ms
interface report() periodic triggers bumped {}
output bumped: Range { distance = 1.0 if (bumps & 3) == 0 else 0.0 }
"""


def test_watch_shows_each_sensors_age(rdisc, tmp_path: Path) -> None:
    source = tmp_path / "bumping.rdis"
    source.write_text(BUMPING, encoding="utf-8")
    with pty_device(_answering(0b10)) as dev:
        result = rdisc("run", source, "--port", dev.port, "--watch", "--duration", "0.5")
    assert result.returncode == 0, result.stderr
    messages = [json.loads(line) for line in result.stdout.splitlines()]
    assert len(messages) >= 3
    assert {(m["name"], m["contents"]["distance"]) for m in messages} == {("bumped", 0.0)}
    ages = [m["sensor_ages"]["bumps"] for m in messages]
    assert all(0.0 <= age < 1.0 for age in ages), ages  # read within the cache time, or just now
    assert _requests(dev.received) < len(messages)  # the 40 Hz output read the kept value


def test_a_sensor_goes_to_json_and_back(rdisc, tmp_path: Path) -> None:
    source = tmp_path / "bumping.rdis"
    source.write_text(BUMPING, encoding="utf-8")
    built, back = tmp_path / "bumping.json", tmp_path / "back.rdis"
    assert rdisc("build", source, "-o", built).returncode == 0
    document = json.loads(built.read_text(encoding="utf-8"))
    assert document["sensors"] == [{"name": "bumps", "type": "int", "primitive": "bumpers", "cache": 100}]
    result = rdisc("import", built, "-o", back)
    assert result.returncode == 0, result.stderr
    assert "sensor bumps: int from bumpers() cache 100 ms\n" in back.read_text(encoding="utf-8")
    assert rdisc("build", back, "-o", tmp_path / "again.json").returncode == 0
    assert json.loads((tmp_path / "again.json").read_text(encoding="utf-8")) == document


def test_the_checker_names_an_unknown_primitive_and_lets_an_input_read_a_sensor(rdisc, tmp_path: Path) -> None:
    source = tmp_path / "wrong.rdis"
    source.write_text(BUMPING + """\
sensor lost: int from bumper() cache 100 ms
primitive drive(speed: int) on oi pack ">Bh" (137, speed)
interface go(speed: int) { drive(speed) }
input set_velocity: DifferentialSpeed -> go(bumps)
""", encoding="utf-8")
    result = rdisc("check", "--format", "json", source)
    assert result.returncode == 1
    found = [(d["code"], d["message"]) for d in json.loads(result.stdout)]
    assert found == [("E102", "unknown primitive `bumper`")]  # an input's sensor is read first (test_sensor_inputs)


def test_the_console_page_lists_a_sensor_with_its_cache_time() -> None:
    from rdisc.console.page import render

    compilation = compile_path(str(CREATE))
    assert compilation.model is not None
    page = render(compilation.model, lambda span: None)
    assert ('<tr data-name="bumperStates"><th>bumperStates</th><td data-value></td>'
            '<td class="type">int sensor, kept 100 ms</td></tr>') in page


def test_the_editor_knows_a_sensor(tmp_path: Path) -> None:
    """The language server indexes a sensor: a variable where it is declared and read, its
    primitive a reference, and a hover that shows the declaration."""
    from lsprotocol import types

    from rdisc.editor import hover, navigation, symbols
    from rdisc.editor.documents import Workspace

    path = tmp_path / "bumping.rdis"
    workspace = Workspace()
    workspace.open(path.as_uri(), str(path), BUMPING, 1)
    analysis = workspace.analysis(path.as_uri())
    assert analysis is not None
    lines = BUMPING.splitlines()
    line = next(i for i, text in enumerate(lines) if text.startswith("sensor"))
    where = types.Position(line=line, character=len("sensor b"))
    found = hover.hover(analysis, None, where)
    assert found is not None and isinstance(found.contents, types.MarkupContent)
    assert found.contents.value.startswith("```rdis\nsensor bumps: int from bumpers() cache 100 ms\n```")
    assert [p.range.start.line for p in navigation.references(analysis, where, False, [])] == [5]  # the output
    data = symbols.semantic_tokens(analysis).data
    kinds = {symbols.TOKEN_TYPES[data[i + 3]] for i in range(0, len(data), 5)}
    assert "variable" in kinds


def test_dump_names_the_sensor_a_primitive_reads(rdisc) -> None:
    result = rdisc("dump", CREATE)
    assert result.returncode == 0, result.stderr
    bumpers = result.stdout[result.stdout.index("primitive bumpers() on btserial"):]
    assert bumpers.splitlines()[-1] == "  out[0] is sensor bumperStates, kept 100 ms"
