"""The simulated twin answers a primitive with its declared `error` reply when told to
(`Simulation.answer_error`, `rdisc sim --error P=CODE`): the call raises RdisDeviceError with the
code and its name from the enum, as the device's Modbus exception would, in the runtime and a
generated driver alike (the driver's own error class), so a driver's error path runs without
hardware."""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("mujoco")

from rdisc.compile import compile_path
from rdisc.sim import Simulation
from tests.conftest import run_rdisc
from tests.engine.test_one_engine import implementation_of

ROOT = Path(__file__).resolve().parents[2]
# examples/modbus.rdis with a body to simulate: one box
MODBUS = (ROOT / "examples" / "modbus.rdis").read_text(encoding="utf-8") + (
    "\nlink base { collision box(0.1, 0.1, 0.05) mass 1 inertia [0.001, 0.001, 0.001] }\n")


def _twin(tmp_path: Path) -> Simulation:
    source = tmp_path / "modbus_body.rdis"
    source.write_text(MODBUS, encoding="utf-8")
    model = compile_path(str(source)).model
    assert model is not None
    return Simulation(model)


@pytest.mark.parametrize("kind", ["runtime", "driver"])
def test_a_primitive_told_to_fail_raises_the_device_error_named_by_its_enum(kind: str, tmp_path: Path) -> None:
    sim = _twin(tmp_path)
    description = implementation_of(kind, MODBUS, tmp_path, "modbus_body")
    with description.connect(sim=sim, threads=False) as robot:
        robot.call_primitive("read_holding", 3)  # answered as ever: the expect's byte count, zeros
        assert robot.state["holding"] == (0, 0)
        sim.answer_error("read_holding", "ILLEGAL_DATA_ADDRESS")
        with pytest.raises(Exception) as failed:  # a driver's error class is its own
            robot.call_primitive("read_holding", 3)
        error = failed.value
        assert type(error).__name__ == "RdisDeviceError"
        assert isinstance(error, description.RdisDeviceError if kind == "driver" else Exception)
        assert (str(error), error.code, error.name, error.values) == (
            "read_holding: the device answered error 2 (ILLEGAL_DATA_ADDRESS)", 2, "ILLEGAL_DATA_ADDRESS", (2,))
        robot.call_primitive("read_input", 1)  # only the primitive told to fail does
        sim.answer_error("write_register", 0x04)
        with pytest.raises(Exception) as failed:
            robot.call_primitive("write_register", 1, 2)
        assert (failed.value.code, failed.value.name) == (4, "SERVER_DEVICE_FAILURE")
        assert robot.state["written"] == 0  # no post-action ran
        sim.answer_error("write_register", 7)
        with pytest.raises(Exception) as failed:
            robot.call_primitive("write_register", 1, 2)
        assert str(failed.value) == "write_register: the device answered error 7 (not a member of Exception)"
        assert (failed.value.code, failed.value.name) == (7, None)
        sim.answer_error("read_holding", None)  # answered again
        robot.call_primitive("read_holding", 3)


def test_what_cannot_be_answered_is_refused_with_a_message(tmp_path: Path) -> None:
    sim = _twin(tmp_path)
    refusals = [
        (("nothing", 2), "modbus has no primitive named 'nothing'"),
        (("read_holding", "NOPE"), ("read_holding: 'NOPE' is no code of its error reply (its codes: ILLEGAL_FUNCTION, "
                                   "ILLEGAL_DATA_ADDRESS, ILLEGAL_DATA_VALUE, SERVER_DEVICE_FAILURE, ACKNOWLEDGE, "
                                   "SERVER_DEVICE_BUSY, MEMORY_PARITY_ERROR, GATEWAY_PATH_UNAVAILABLE, "
                                   "GATEWAY_TARGET_FAILED)")),
        (("read_holding", 256), "read_holding: code 256 does not fit its error reply's first value (B)"),
    ]
    for (primitive, code), message in refusals:
        with pytest.raises(ValueError) as refused:
            sim.answer_error(primitive, code)
        assert str(refused.value) == message


def test_rdisc_sim_error_answers_the_call_with_the_device_error(tmp_path: Path) -> None:
    source = tmp_path / "modbus_body.rdis"
    source.write_text(MODBUS, encoding="utf-8")
    done = run_rdisc("sim", str(source), "--error", "read_holding=ILLEGAL_DATA_ADDRESS", "--call", "read_holding",
                     "start=3")
    assert done.returncode == 1
    assert done.stderr.splitlines()[-1].endswith(
        "RdisDeviceError: read_holding: the device answered error 2 (ILLEGAL_DATA_ADDRESS)")
    done = run_rdisc("sim", str(source), "--error", "read_holding", "--call", "read_holding", "start=3")
    assert (done.returncode, done.stderr) == (2, "rdisc sim: --error read_holding: give it as PRIMITIVE=CODE\n")
    done = run_rdisc("sim", str(source), "--error", "read_holding=0x1", "--call", "read_input", "address=1")
    assert (done.returncode, done.stderr) == (0, "")  # only read_holding fails


def test_rdisc_console_sim_error_answers_the_pages_call_with_the_device_error(tmp_path: Path) -> None:
    """`rdisc console --sim --error P=CODE`, parsed as `rdisc sim` parses it: a page's call of P is
    answered with the device's error, another primitive's as ever."""
    import json
    import signal

    from websockets.sync.client import connect

    from tests.conftest import console_origin, console_ws, start_console, stop_process

    source = tmp_path / "modbus_body.rdis"
    source.write_text(MODBUS, encoding="utf-8")
    process, line, url = start_console(source, "--sim", "--error", "read_holding=ILLEGAL_DATA_ADDRESS")
    try:
        assert line.startswith("rdisc console: modbus, simulated, on "), line
        with connect(console_ws(url), origin=console_origin(url)) as ws:
            assert json.loads(ws.recv(timeout=30))["type"] == "hello"
            results = []
            for ident, name, values in [(1, "read_holding", {"start": "3"}), (2, "read_input", {"address": "1"})]:
                ws.send(json.dumps({"id": ident, "kind": "primitive", "name": name, "values": values}))
                while (message := json.loads(ws.recv(timeout=30)))["type"] != "result":
                    pass
                results.append(message)
        assert results == [
            {"type": "result", "id": 1, "ok": False, "error": "RdisDeviceError",
             "message": "read_holding: the device answered error 2 (ILLEGAL_DATA_ADDRESS)"},
            {"type": "result", "id": 2, "ok": True},
        ]
    finally:
        status, stderr = stop_process(process, signal.SIGTERM)
    assert status == 143 and "Traceback" not in stderr, stderr


@pytest.mark.parametrize(("args", "message"), [
    (["--sim", "--error", "read_holding"], "rdisc console: --error read_holding: give it as PRIMITIVE=CODE\n"),
    (["--sim", "--error", "nothing=2"], "rdisc console: --error nothing=2: modbus has no primitive named 'nothing'\n"),
    (["--port", "loop://", "--error", "read_holding=2"], "rdisc console: --error is for --sim\n"),
])
def test_rdisc_console_refuses_an_error_it_cannot_answer(tmp_path: Path, args: list[str], message: str) -> None:
    source = tmp_path / "modbus_body.rdis"
    source.write_text(MODBUS, encoding="utf-8")
    done = run_rdisc("console", str(source), *args, "--http", "127.0.0.1:0")
    assert (done.returncode, done.stderr) == (2, message)
