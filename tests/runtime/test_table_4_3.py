"""Thesis Table 4.3: the six inputs of `set_velocity` give the "Expected" column.

The bytes are computed through the checked Model of examples/create.rdis by the
expression interpreter: input arguments → interface → primitive format arguments
→ struct pack. (Issue 3's runtime and generated driver repeat this over a pty.)
"""

from __future__ import annotations

import struct
from pathlib import Path

import pytest
from devices.create import TABLE_4_3

from rdisc.compile import compile_path
from rdisc.semantics import model as m
from rdisc.semantics.evaluate import coerce, evaluate

CREATE = Path(__file__).parents[2] / "examples" / "create.rdis"

@pytest.fixture(scope="module")
def model() -> m.Model:
    compilation = compile_path(str(CREATE))
    assert compilation.model is not None, compilation.diagnostics.items
    return compilation.model


def bind(params: tuple[m.Parameter, ...], values: list[m.Value]) -> dict[str, m.Value]:
    return {p.name: coerce(v, p.type) for p, v in zip(params, values)}


def bytes_of_input(model: m.Model, name: str, fields: dict[str, float]) -> list[bytes]:
    state = {s.name: s.initial for s in model.states.values()}
    domain_input = model.inputs[name]
    interface = model.interfaces[domain_input.interface]
    names = {**state, **fields}
    iface_env = {**state, **bind(interface.params, [evaluate(a, names) for a in domain_input.args])}
    written = []
    for call in interface.run_order():
        primitive = model.primitives[call.primitive]
        env = {**state, **bind(primitive.params, [evaluate(a, iface_env) for a in call.args])}
        values = [evaluate(a, env) for a in primitive.args]
        assert isinstance(primitive.encoding, m.Pack)
        written.append(struct.pack(primitive.encoding.format, *values))
    return written


@pytest.mark.parametrize(("given", "expected"), TABLE_4_3, ids=[str(row[0]) for row in TABLE_4_3])
def test_set_velocity_sends_the_expected_column(model, given, expected) -> None:
    linear, angular = given
    assert bytes_of_input(model, "set_velocity", {"linear": linear, "angular": angular}) == [
        struct.pack(">Bhh", *expected)
    ]


@pytest.mark.parametrize(("linear", "angular"), [(0.9, 0.0), (-3.0, 0.5), (1.0, 0.1), (0.1, -0.01)])
def test_set_velocity_keeps_to_the_open_interface_limits(model, linear, angular) -> None:
    """Speed within ±500 mm/s; radius within ±2000 mm or the special 32767 (straight)."""
    ((opcode, velocity, radius),) = (
        struct.unpack(">Bhh", b) for b in bytes_of_input(model, "set_velocity", {"linear": linear, "angular": angular})
    )
    assert opcode == 137 and -500 <= velocity <= 500
    assert radius == 32767 or -2000 <= radius <= 2000
