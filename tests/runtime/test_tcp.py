"""A `tcp` connection: a device behind a real TCP socket on loopback (an Ethernet
serial server, a simulator), opened from the description's `address`, by the
runtime and by the generated driver alike."""

from __future__ import annotations

import socket
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

from rdisc.emit.python import import_driver
from rdisc.runtime import load

DESCRIPTION = """\
robot tcp_box {{ author "tests" }}
state reading: int = 0
frame packet {{ header "\\xAA" length "B" = payload payload checksum "xor" "B" }}
connection net: tcp {{ address "socket://127.0.0.1:{port}" }}
primitive read(channel: int) on net frame packet pack "BB" (0x10, channel) unpack ">h" {{ reading = out[0] }}
"""


class Server:
    """Answers each framed request `AA 02 10 ch x` with a framed reply: the channel times -100."""

    def __init__(self) -> None:
        self.listener = socket.create_server(("127.0.0.1", 0))
        self.port = self.listener.getsockname()[1]
        self.received = bytearray()
        self.thread = threading.Thread(target=self.serve, daemon=True)
        self.thread.start()

    def serve(self) -> None:
        while True:
            try:
                conn, _ = self.listener.accept()
            except OSError:
                return
            with conn:
                while data := conn.recv(64):
                    self.received += data
                    value = (-100 * data[3]).to_bytes(2, "big", signed=True)
                    body = bytes([2]) + value
                    check = 0
                    for byte in body:
                        check ^= byte
                    conn.sendall(b"\xaa" + body + bytes([check]))

    def close(self) -> None:
        self.listener.close()


@pytest.fixture
def server() -> Iterator[Server]:
    s = Server()
    yield s
    s.close()


@pytest.fixture
def description(server: Server, tmp_path: Path) -> Path:
    path = tmp_path / "tcp_box.rdis"
    path.write_text(DESCRIPTION.format(port=server.port))
    return path


def test_runtime_opens_the_address(server: Server, description: Path) -> None:
    with load(description).connect(timeout=1.0) as robot:
        robot.call_primitive("read", 3)
        assert robot.state["reading"] == -300
    assert bytes(server.received) == bytes([0xAA, 2, 0x10, 3, 2 ^ 0x10 ^ 3])


def test_generated_driver_opens_the_address(server: Server, description: Path, tmp_path: Path) -> None:
    driver = import_driver(description, tmp_path)
    with driver.connect(timeout=1.0) as robot:
        robot.call_primitive("read", 7)
        assert robot.state["reading"] == -700
    assert bytes(server.received) == bytes([0xAA, 2, 0x10, 7, 2 ^ 0x10 ^ 7])


def test_rdisc_run_without_port_uses_the_address(server: Server, description: Path, rdisc) -> None:
    result = rdisc("run", str(description), "--call", "read", "channel=5", "--duration", "0")
    assert result.returncode == 0, result.stderr
    assert bytes(server.received) == bytes([0xAA, 2, 0x10, 5, 2 ^ 0x10 ^ 5])
