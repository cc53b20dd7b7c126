"""One semantics, two implementations: the rdisc runtime (interpreting the Model) and
the driver `rdisc emit-python` generates, driven with the same random sequences of
inputs, ticks and device replies, must write the same bytes, reach the same state,
deliver the same outputs and raise or report the same errors.

The port is a scripted in-memory object (both implementations accept an open
pyserial-like port): it records what is written and answers reads from a script
of reply bytes that hypothesis draws, valid and corrupt alike. Delays are set to
0 ms so a run takes microseconds; timing is tested over real ptys elsewhere.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import pytest
from conftest import fuzz_examples
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from rdisc.compile import compile_path
from rdisc.emit.python import import_driver
from rdisc.runtime import load
from tests.support.ports import ScriptedPort

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

ROOT = Path(__file__).resolve().parents[1]
EXAMPLES = [
    "examples/create.rdis",
    "examples/koala.rdis",
    "tests/runtime/data/fast_create.rdis",
    "tests/runtime/data/cr_device.rdis",  # reply lines end in "\r"
    "tests/runtime/data/framed_servo.rdis",  # frames: length, sums, CRCs, acknowledgements, resync
]


def _without_delays(example: str, folder: Path) -> Path:
    text = re.sub(r"delay\s+[0-9.]+\s*(ms|s)\b", "delay 0 ms", (ROOT / example).read_text())
    path = folder / Path(example).name
    path.write_text(text)
    return path


@pytest.fixture(scope="module", params=EXAMPLES, ids=[Path(e).stem for e in EXAMPLES])
def pair(request, tmp_path_factory):
    """(runtime Description, generated driver module, model) for one example."""
    folder = tmp_path_factory.mktemp(Path(request.param).stem)
    path = _without_delays(request.param, folder)
    compilation = compile_path(str(path))
    assert compilation.model is not None, compilation.diagnostics.items
    driver = import_driver(path, folder, f"driver_{Path(request.param).stem}")
    return load(compilation.model), driver, compilation.model


# Replies: bytes a device might send, valid and corrupt, for binary and ASCII protocols.
_LINES = st.sampled_from([
    b"d\r\n", b"g\r\n", b"e,12,-5\r\n", b"h,1000,-2000\r\n", b"e,x,1\r\n", b"h,1\n", b"\r\n",
    b"L,42,mm\r", b"L,-7,cm\r", b"ok\r", b"L,x\r", b"\r",
])
_PROXIMITY = st.lists(st.integers(0, 1023), min_size=16, max_size=16).map(
    lambda v: b"n," + b",".join(str(x).encode() for x in v) + b"\r\n"
)


def _status(fields: tuple[int, bytes, bool]) -> bytes:
    """A Dynamixel status frame from servo `ident`, its checksum right or spoilt."""
    ident, payload, spoilt = fields
    body = bytes([ident, len(payload) + 1]) + payload
    return b"\xff\xff" + body + bytes([(~sum(body) & 0xFF) ^ spoilt])


def _crc_reply(fields: tuple[bytes, bool]) -> bytes:
    """A reply to `80 10` with its CRC-16/XMODEM over the request and the data, right or spoilt."""
    data, spoilt = fields
    crc = 0
    for byte in b"\x80\x10" + data:
        crc ^= byte << 8
        for _ in range(8):
            crc = ((crc << 1) ^ 0x1021 if crc & 0x8000 else crc << 1) & 0xFFFF
    return data + (crc ^ spoilt).to_bytes(2, "big")


_FRAMES = st.one_of(
    st.tuples(st.sampled_from([1, 1, 1, 2]), st.binary(min_size=0, max_size=4), st.booleans()).map(_status),
    st.tuples(st.binary(min_size=4, max_size=4), st.booleans()).map(_crc_reply),
    st.just(b"\xff"),
)
_CHUNK = st.one_of(st.binary(min_size=0, max_size=4), _LINES, _PROXIMITY, st.just(b"\x00"), st.just(b"\x03"),
                   _FRAMES)
_SCRIPT = st.lists(_CHUNK, max_size=40).map(b"".join)
_NUMBER = st.one_of(
    st.floats(-3.0, 3.0, allow_nan=False),
    st.sampled_from([0.0, -0.0, 0.2, -0.2, 0.4, -0.4, 1e-9, 5e5, float("inf"), float("nan")]),
    st.integers(-3, 3),
)


def _operations(model):
    inputs = [
        st.tuples(st.just("input"), st.just(name), st.tuples(*[_NUMBER for _ in model.adapters[i.adapter].fields]))
        for name, i in model.inputs.items()
    ]
    return st.lists(st.one_of(st.just(("tick", "", ())), *inputs), max_size=12)


def _error(err: BaseException) -> tuple[str, str]:
    """What the contract fixes of an error: its type and the element at fault, which
    its message names first (the rest is Python's wording, which may differ)."""
    return type(err).__name__, str(err).split(":")[0]


def _run(robot, model, operations) -> list[Any]:
    """What an implementation does for the operations: one entry per operation."""
    trace: list[Any] = []
    for kind, name, values in operations:
        try:
            if kind == "tick":
                robot.tick()
            else:
                fields = [f.name for f in model.adapters[model.inputs[name].adapter].fields]
                robot.call_input(name, **dict(zip(fields, values)))
            outcome: Any = "ok"
        except Exception as err:  # noqa: BLE001 - the error is what is compared
            outcome = _error(err)
        trace.append((kind, name, outcome, dict(robot.state)))
    return trace


def _drive(make, model, script: bytes, operations) -> tuple[bytes, list[Any], list[Any], list[Any]]:
    port = ScriptedPort(script)
    outputs: list[Any] = []
    errors: list[Any] = []

    def report(err: BaseException) -> None:
        errors.append(_error(err))

    try:
        robot = make(port, outputs.append, report)
    except Exception as err:  # noqa: BLE001 - a failing startup is compared too
        return bytes(port.written), [("connect", _error(err))], outputs, errors
    try:
        trace = _run(robot, model, operations)
    finally:
        robot.close()
    return bytes(port.written), trace, outputs, errors


@settings(max_examples=fuzz_examples(100), deadline=None, derandomize=True,
          suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(data=st.data())
def test_runtime_and_generated_driver_agree(pair, data) -> None:
    description, driver, model = pair
    script = data.draw(_SCRIPT, label="replies")
    operations = data.draw(_operations(model), label="operations")

    def runtime(port, on_output, on_error):
        return description.connect(port, threads=False, on_output=on_output, on_error=on_error)

    def generated(port, on_output, on_error):
        return driver.connect(port, threads=False, on_output=on_output, on_error=on_error)

    assert _drive(generated, model, script, operations) == _drive(runtime, model, script, operations)
