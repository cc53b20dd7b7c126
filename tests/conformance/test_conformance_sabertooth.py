"""examples/sabertooth.rdis against pysabertooth (0.4.0), the published Sabertooth driver, byte for
byte: pysabertooth's own Sabertooth class runs over a port that records what it writes (its
pyserial and its sleeps replaced in its module), and rdisc must write the same bytes for the same
calls: the autobaud bytes and baud rate it opens with, each motor driven at speeds in percent,
both at once, stopped, any command, at every address. The runtime and the generated driver alike.
"""

from __future__ import annotations

import types
from pathlib import Path
from typing import Any

import pytest

driver = pytest.importorskip("pysabertooth.PySabertooth")

from tests.engine.test_one_engine import ScriptedPort, implementation_of

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "sabertooth.rdis"
BAUDS = {2400: 1, 9600: 2, 19200: 3, 38400: 4, 115200: 5}


class Serial(ScriptedPort):
    """pyserial's Serial as pysabertooth makes it (no arguments, then `open()`): the one fake
    port, silent, closed until opened; the writes are recorded."""

    def __init__(self) -> None:
        super().__init__()
        self.is_open = False

    def open(self) -> None:
        self.is_open = True

    def close(self) -> None:
        super().close()
        self.is_open = False


@pytest.fixture
def sabertooth(monkeypatch: pytest.MonkeyPatch) -> Any:
    """pysabertooth's Sabertooth, made for an address and a baud rate, on a recording port."""
    monkeypatch.setattr(driver, "serial", types.SimpleNamespace(Serial=Serial))
    monkeypatch.setattr(driver, "time", types.SimpleNamespace(sleep=lambda seconds: None))

    def make(address: int = 128, baudrate: int = 9600) -> Any:
        made = driver.Sabertooth("/dev/ttySABER", baudrate=baudrate, address=address)
        made.__class__ = type("Kept", (driver.Sabertooth,), {"__del__": lambda self: None})  # no stop when collected
        return made
    return make


@pytest.fixture(scope="module", params=["runtime", "driver"])
def ours(request: pytest.FixtureRequest, tmp_path_factory: pytest.TempPathFactory) -> tuple[str, Any]:
    folder = tmp_path_factory.mktemp("sabertooth")
    return request.param, implementation_of(request.param, EXAMPLE.read_text(encoding="utf-8"), folder, "sabertooth")


def written(ours: tuple[str, Any], address: int, *calls: tuple[str, str, tuple[Any, ...]]) -> bytes:
    """What rdisc writes for primitive and interface calls at an address."""
    kind, implementation = ours
    port = ScriptedPort(b"")
    settings = {"ADDRESS": address}
    robot = (implementation.connect(port, threads=False, settings=settings) if kind == "runtime"
             else implementation.connect(port, threads=False, **settings))
    with robot:
        for what, name, args in calls:
            getattr(robot, f"call_{what}")(name, *args)
    return bytes(port.written)


@pytest.mark.parametrize("address", range(128, 136))
@pytest.mark.parametrize("baudrate", sorted(BAUDS))
def test_opening_writes_the_autobaud_bytes_and_baud_rate(sabertooth: Any, ours: tuple[str, Any], address: int,
                                                         baudrate: int) -> None:
    expected = bytes(sabertooth(address, baudrate).saber.written)
    assert written(ours, address, ("primitive", "autobaud", ()), ("primitive", "autobaud", ()),
                   ("interface", "set_baud", (BAUDS[baudrate],))) == expected


@pytest.mark.parametrize("address", [128, 131, 135])
@pytest.mark.parametrize("motor", [1, 2])
@pytest.mark.parametrize("percent", [0, 1, 37, 50, 99, 100, -1, -37, -100])
def test_driving_a_motor(sabertooth: Any, ours: tuple[str, Any], address: int, motor: int, percent: int) -> None:
    made = sabertooth(address)
    made.saber.written.clear()
    made.drive(motor, percent)
    assert written(ours, address, ("primitive", "drive", (motor, percent))) == bytes(made.saber.written)


@pytest.mark.parametrize(("first", "second"), [(0, 0), (100, -100), (-25, 75)])
def test_driving_both_and_stopping(sabertooth: Any, ours: tuple[str, Any], first: int, second: int) -> None:
    made = sabertooth(129)
    made.saber.written.clear()
    made.driveBoth(first, second)
    made.stop()
    assert written(ours, 129, ("interface", "drive_both", (first, second)), ("interface", "stop", ())) == bytes(
        made.saber.written)


@pytest.mark.parametrize(("command", "value"), [(8, 64), (9, 127), (10, 0), (11, 5), (16, 20), (7, 127)])
def test_any_command(sabertooth: Any, ours: tuple[str, Any], command: int, value: int) -> None:
    made = sabertooth(130)
    made.saber.written.clear()
    made.sendCommand(command, value)
    assert written(ours, 130, ("primitive", "command", (command, value))) == bytes(made.saber.written)
