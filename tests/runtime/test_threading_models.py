"""Threading models (`threading single | dual | multiple`), on a scripted pty device that
answers slowly, through the runtime and a generated driver alike.

What a host's command waits for is asserted as order and counts on the wire, never as times:
under `single` a command waits for the whole tick in flight (the periodic requests before it
are whole ticks); under `dual` and `multiple` for the one exchange in flight only (it is
written between two periodic requests of one tick). Under `multiple` each periodic interface
is its own thread at its own rate: their requests come in the ratio of their rates.
"""

from __future__ import annotations

import importlib.util
import sys
import threading
from pathlib import Path
from types import ModuleType

import pytest
from devices import PtyDevice

from rdisc.compile import compile_path
from rdisc.emit.python import to_python
from rdisc.runtime import load

TICK = ("A", "B", "A", "B")  # one tick's requests: four exchanges, each answered late

SLOW = """\
robot threads25 {{ author "tests" }}

connection link: serial {{
    baud 115200
    threading {model} at {hz} Hz
    keepalive ping() every 200 ms
}}

primitive ask_a() on link format "A\\n" () regex r"^a\\s*$"
primitive ask_b() on link format "B\\n" () regex r"^b\\s*$"
primitive go() on link format "C\\n" ()
primitive ask_k() on link format "K\\n" () regex r"^k\\s*$"

interface poll() periodic {{ ask_a() ask_b() ask_a() ask_b() }}
interface ping() {{ ask_k() }}
interface command() {{ go() }}
"""

RATES = """\
robot threads25 {{ author "tests" }}

connection link: serial {{ baud 115200 threading {model} at 20 Hz }}

primitive ask_f() on link format "F\\n" () regex r"^f\\s*$"
primitive ask_s() on link format "S\\n" () regex r"^s\\s*$"

interface fast() periodic {{ ask_f() }}
interface slow() periodic 5 Hz {{ ask_s() }}
"""


class LineDevice(PtyDevice):
    """Answers each request line `X` with `x` after `delay` seconds (`C`, a command: no answer),
    and keeps the request lines in the order they came. It answers from a timer, reading on
    meanwhile, so it sees a command written while an exchange waits for its answer (`cut_in`)."""

    def __init__(self, delay: float) -> None:
        super().__init__()
        self.delay = delay
        self.lines: list[str] = []
        self.cut_in: list[str] = []  # the requests that came while an answer was pending
        self._pending = 0
        self._partial = b""

    def handle(self, data: bytes) -> None:
        self._partial += data
        while b"\n" in self._partial:
            line, self._partial = self._partial.split(b"\n", 1)
            request = line.decode("ascii")
            with self._cond:
                self.lines.append(request)
                if self._pending:
                    self.cut_in.append(request)
                self._cond.notify_all()
            if request == "C":
                continue
            answer = request.lower().encode("ascii") + b"\n"
            if not (self.delay and request in "AB"):
                self.send(answer)
                continue
            with self._cond:
                self._pending += 1
            threading.Timer(self.delay, self._answer, (answer,)).start()

    def _answer(self, answer: bytes) -> None:
        with self._cond:
            self._pending -= 1
        self.send(answer)

    def count(self, request: str) -> int:
        with self._cond:
            return self.lines.count(request)


def driver(source: Path, folder: Path) -> ModuleType:
    """The driver `rdisc emit-python` writes for `source`, imported from `folder`."""
    compilation = compile_path(str(source))
    assert compilation.model is not None, compilation.diagnostics.items
    path = folder / f"{source.stem}_driver.py"
    path.write_text(to_python(compilation.model, source.name, sources=compilation.sources), encoding="utf-8")
    spec = importlib.util.spec_from_file_location(f"{path.stem}_{abs(hash(str(path)))}", path)
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    sys.modules[spec.name] = module
    spec.loader.exec_module(module)
    return module


def connect(way: str, source: Path, port: str, tmp_path: Path):  # a Robot of either kind
    """The robot of `source` on `port`: by the runtime, or by a driver generated from it."""
    if way == "runtime":
        return load(source).connect(port)
    return driver(source, tmp_path).connect(port)


def threads_of(robot_name: str) -> list[str]:
    return sorted(t.name for t in threading.enumerate() if t.name.startswith(f"{robot_name} "))


@pytest.mark.parametrize("way", ["runtime", "driver"])
@pytest.mark.parametrize(("model", "whole_ticks"), [("single", True), ("dual", False), ("multiple", False)])
def test_a_command_waits_for_the_tick_under_single_and_one_exchange_otherwise(way, model, whole_ticks,
                                                                              tmp_path) -> None:
    source = tmp_path / "slow.rdis"
    source.write_text(SLOW.format(model=model, hz=1), encoding="utf-8")
    with LineDevice(delay=0.15) as dev:  # a tick: four exchanges of 0.15 s, then the rest of its 1 s
        robot = connect(way, source, dev.port, tmp_path)
        try:
            dev.wait_until(lambda: "A" in dev.lines, 5.0, "the first tick")
            robot.call_interface("command")  # during the first tick's first exchange (it lasts 0.6 s)
            lines = dev.wait_until(lambda: "C" in dev.lines, 5.0, "the command") and list(dev.lines)
            cut_in = list(dev.cut_in)
        finally:
            robot.close()
    periodic = [line for line in lines[:lines.index("C")] if line in "AB"]
    assert tuple(periodic) == (TICK * 2)[:len(periodic)], lines
    # single: the whole tick in flight first (4 requests; 8 had the call come in the next tick);
    # dual, multiple: the exchange in flight only, so the command comes within a tick (1 to 3)
    assert periodic and (len(periodic) % len(TICK) == 0) == whole_ticks, lines
    assert cut_in == [], lines  # never written while an exchange waits for its answer


@pytest.mark.parametrize("way", ["runtime", "driver"])
def test_multiple_runs_each_interface_at_its_own_rate(way, tmp_path) -> None:
    source = tmp_path / "rates.rdis"
    source.write_text(RATES.format(model="multiple"), encoding="utf-8")
    with LineDevice(delay=0.0) as dev:
        robot = connect(way, source, dev.port, tmp_path)
        try:
            dev.wait_until(lambda: dev.lines.count("S") >= 5, 10.0, "five requests of `slow`")
        finally:
            robot.close()
        fast, slow = dev.count("F"), dev.count("S")
    # 20 Hz against 5 Hz: four to one over the run; a busy machine skips ticks, never bursts them
    assert 2 * (slow - 1) <= fast <= 4 * (slow + 1) + 1, (fast, slow)


def test_single_runs_every_interface_at_the_connection_rate(tmp_path) -> None:
    """The same interfaces on a `single` connection (W230: the rate is not used): one each tick."""
    source = tmp_path / "rates.rdis"
    source.write_text(RATES.format(model="single"), encoding="utf-8")
    with LineDevice(delay=0.0) as dev:
        robot = load(source).connect(dev.port)
        try:
            dev.wait_until(lambda: dev.lines.count("S") >= 5, 10.0, "five requests of `slow`")
        finally:
            robot.close()
        lines = list(dev.lines)
    assert lines[:10] == ["F", "S"] * 5, lines


@pytest.mark.parametrize("way", ["runtime", "driver"])
@pytest.mark.parametrize(("model", "names"), [
    ("single", ["threads25 link"]),
    ("dual", ["threads25 link"]),
    ("multiple", ["threads25 link fast", "threads25 link keepalive", "threads25 link slow"]),
])
def test_close_ends_every_thread_of_the_model(way, model, names, tmp_path) -> None:
    source = tmp_path / "rates.rdis"
    source.write_text(RATES.format(model=model).replace("20 Hz }", "20 Hz keepalive fast() every 1 s }"),
                      encoding="utf-8")
    with LineDevice(delay=0.0) as dev:
        robot = connect(way, source, dev.port, tmp_path)
        try:
            dev.wait_until(lambda: "S" in dev.lines, 5.0, "the first request of `slow`")
            assert threads_of("threads25") == names
        finally:
            robot.close()
        assert threads_of("threads25") == []


def test_the_port_lock_of_dual_goes_to_the_waiting_thread_before_its_holder_takes_it_again() -> None:
    """The periodic thread releases the port after an exchange and asks for it at once for the
    next: a command already waiting gets it first (a plain lock lets the holder take it back)."""
    from rdisc.engine.ports import _FairLock

    lock, order = _FairLock(), []
    lock.acquire()
    lock.acquire()  # re-entrant, as the port's own lock

    def command() -> None:
        lock.acquire()
        order.append("command")
        lock.release()

    waiter = threading.Thread(target=command)
    waiter.start()
    while not lock._queue:  # the command waits for the port
        waiter.join(0.001)
    lock.release()
    lock.release()
    lock.acquire()  # the next exchange
    order.append("periodic")
    lock.release()
    waiter.join(5)
    assert order == ["command", "periodic"]
    with pytest.raises(RuntimeError):
        lock.release()
