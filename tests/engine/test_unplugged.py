"""A device unplugged in the middle of a reply is an RdisConnectionError of its connection, in
the runtime and a driver alike, never pyserial's SerialException (issue 20): the port's read
fails, and so does giving the port its timeout back once the exchange ends."""

from __future__ import annotations

from pathlib import Path

import pytest
import serial

from rdisc.runtime import RdisConnectionError
from tests.engine.test_one_engine import implementation_of
from tests.support.ports import ScriptedPort

DESCRIPTION = """\
robot unplugged { author "tests" }
connection link: serial { baud 9600 }
state value: int = 0
frame packet() { header "\\xAA" length "B" = payload payload }
primitive query() on link frame packet() pack "B" (1) unpack "<HH" { value = out[0] }
"""


HALF = [b"\xaa", b"\x04"]  # the header and the length; then the device is gone


class UnpluggedPort(ScriptedPort):
    """Gives half a reply (its script), then is unplugged: its next read, and giving it a timeout
    after that, fail as pyserial's do."""

    def __init__(self) -> None:
        self.unplugged = False
        self.reads = 0
        super().__init__(b"".join(HALF), timeout=1.0)

    @property  # a plain attribute of the port, which fails once it is unplugged
    def timeout(self) -> float | None:
        return self._timeout

    @timeout.setter
    def timeout(self, value: float | None) -> None:
        if self.unplugged:
            raise serial.SerialException("[Errno 5] Input/output error")
        self._timeout = value

    def read(self, size: int = 1, /) -> bytes:
        self.reads += 1
        if self.script:
            return super().read(size)
        self.unplugged = True
        raise serial.SerialException("device reports readiness to read but returned no data "
                                     "(device disconnected or multiple access on port?)")


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_device_unplugged_mid_reply_is_a_connection_error(tmp_path: Path, kind: str) -> None:
    implementation = implementation_of(kind, DESCRIPTION, tmp_path, f"unplugged_{kind}")
    errors = RdisConnectionError if kind == "runtime" else implementation.RdisConnectionError
    port = UnpluggedPort()
    robot = implementation.connect({"link": port}, threads=False)
    with pytest.raises(errors) as caught:
        robot.call_primitive("query")
    assert str(caught.value) == ("link: device reports readiness to read but returned no data "
                                 "(device disconnected or multiple access on port?)")
    assert port.reads == len(HALF) + 1 and robot.state["value"] == 0
