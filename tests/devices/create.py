"""An emulated iRobot Create (Open Interface) on a pty.

It parses the host's bytes into OI commands and records each one with its arrival
time (`commands`). It answers the Sensors command (142, packet id) with the
packet's bytes: packet 7 is the bumpers byte (`bumpers`), and a few two-byte
packets (19 distance, 20 angle, 22 voltage, 25 charge, 26 capacity) are there
for descriptions with longer replies (`sensors[id] = value`).

`mode`: "normal" answers; "silent" never answers (the host times out); "short"
answers all but the last byte of each reply (nothing at all for packet 7).
"""

from __future__ import annotations

import signal
import struct
import subprocess
import time

from . import PtyDevice

# opcode -> number of data bytes that follow it
DATA_BYTES = {128: 0, 129: 1, 130: 0, 131: 0, 132: 0, 133: 0, 134: 0, 135: 0, 136: 1,
              137: 4, 139: 3, 142: 1, 145: 4}
# sensor packet id -> struct format of its value
PACKETS = {7: "B", 19: ">h", 20: ">h", 21: "B", 22: ">H", 25: ">H", 26: ">H"}

START, FULL, DRIVE, SENSORS = 128, 132, 137, 142
STOP = bytes([DRIVE, 0, 0, 0, 0])

# Thesis Table 4.3, the "Expected" column: what `set_velocity` must send.
TABLE_4_3 = [  # (linear m/s, angular rad/s) -> (opcode, linear mm/s, radius mm), "Expected"
    ((-0.2, -0.4), (137, -200, 500)),
    ((0.0, 0.0), (137, 0, 0)),
    ((0.0, 0.2), (137, 0, -1)),
    ((0.0, -0.2), (137, 0, 1)),
    ((0.2, 0.0), (137, 200, 32767)),
    ((-0.2, 0.0), (137, -200, 32767)),
]


class CreateEmulator(PtyDevice):
    def __init__(self, mode: str = "normal", bumpers: int = 0, reply_delay: float = 0.0) -> None:
        super().__init__()
        self.mode = mode
        self.reply_delay = reply_delay
        self.sensors: dict[int, int] = {7: bumpers, 19: 0, 20: 0, 21: 0, 22: 15000, 25: 2000, 26: 2700}
        self.commands: list[tuple[float, bytes]] = []  # complete OI commands, with arrival times
        self.oi_mode = "off"  # "off", "passive", "full"
        self._pending = bytearray()

    @property
    def bumpers(self) -> int:
        """The "Bumps and Wheel Drops" byte (packet 7): bit 0 right bumper, bit 1 left."""
        return self.sensors[7]

    @bumpers.setter
    def bumpers(self, value: int) -> None:
        self.sensors[7] = value

    def opcodes(self) -> list[int]:
        """The opcode of each command received, in order."""
        with self._cond:
            return [c[0] for _, c in self.commands]

    def drives(self) -> list[tuple[int, int]]:
        """(velocity, radius) of each Drive command received, in order."""
        with self._cond:
            return [struct.unpack(">hh", c[1:]) for _, c in self.commands if c[0] == DRIVE]

    def wait_for_commands(self, n: int, timeout: float = 2.0, opcode: int | None = None) -> list[tuple[float, bytes]]:
        """Wait until `n` commands (with this opcode, if given) arrived; return them."""
        def count() -> int:
            return sum(1 for _, c in self.commands if opcode is None or c[0] == opcode)

        self.wait_until(lambda: count() >= n, timeout, f"{n} commands" + (f" {opcode}" if opcode else ""))
        with self._cond:
            return [(t, c) for t, c in self.commands if opcode is None or c[0] == opcode]

    def signal_once_open(self, process: subprocess.Popen[str], after: float, signals: list[signal.Signals],
                         gap: float) -> str:
        """Send `signals` to `process` `after` seconds after its first command arrived (the port is
        open: from then on the robot must end stopped), `gap` apart; wait for it to end, check that
        the stop command was the last thing written, and return what it printed on stderr (or on
        stdout, if that is where stderr goes)."""
        try:
            self.wait_for_commands(1, timeout=30)
            time.sleep(after)
            for signum in signals:
                process.send_signal(signum)
                time.sleep(gap)
            try:
                stdout, stderr = process.communicate(timeout=30)
            except subprocess.TimeoutExpired:
                raise AssertionError(f"still running 30 s after {[s.name for s in signals]}:\n"
                                     f"{stacks_of(process)}") from None
        finally:
            if process.poll() is None:
                process.kill()
                process.communicate()
        printed = stderr if stderr is not None else stdout
        assert "Traceback" not in printed, printed
        self.wait_until(lambda: bool(self.commands) and self.commands[-1][1] == STOP, 5, "the stop command last")
        time.sleep(0.05)  # nothing more arrives after it
        assert self.commands[-1][1] == STOP, self.commands[-3:]
        return printed

    def _cleared(self) -> None:
        self.commands.clear()
        self._pending.clear()

    def handle(self, data: bytes) -> None:
        now = time.monotonic()
        with self._cond:
            self._pending += data
            complete = []
            while self._pending:
                size = 1 + DATA_BYTES.get(self._pending[0], 0)
                if len(self._pending) < size:
                    break
                command = bytes(self._pending[:size])
                del self._pending[:size]
                self.commands.append((now, command))
                complete.append(command)
        for command in complete:
            self._execute(command)

    def _execute(self, command: bytes) -> None:
        opcode = command[0]
        if opcode == START:
            self.oi_mode = "passive"
        elif opcode == FULL:
            self.oi_mode = "full"
        elif opcode == SENSORS:
            packet = command[1]
            fmt = PACKETS.get(packet)
            if fmt is None or self.mode == "silent":
                return
            reply = struct.pack(fmt, self.sensors.get(packet, 0))
            if self.mode == "short":
                reply = reply[:-1]
            self.send(reply)


def stacks_of(process: subprocess.Popen[str]) -> str:
    """What a process that will not end is doing: every thread's Python stack, which it writes
    on SIGABRT when started with PYTHONFAULTHANDLER=1 (`conftest.cli_env` sets it), and what it
    printed before; it is gone after."""
    process.send_signal(signal.SIGABRT)
    try:
        stdout, stderr = process.communicate(timeout=10)
    except subprocess.TimeoutExpired:
        process.kill()
        stdout, stderr = process.communicate()
    return f"stdout:\n{stdout}\nstderr:\n{stderr}"
