"""Canonical JSON: the thesis shape, exact text, determinism, and reading it back."""

from __future__ import annotations

import json
import math
import subprocess
from pathlib import Path

import pytest
from conftest import run_rdisc_seeded

from rdisc.compile import compile_path
from rdisc.emit.canonical import to_json
from rdisc.semantics import formats
from rdisc.semantics import model as m
from rdisc.semantics.model import Scope, Type

ROOT = Path(__file__).resolve().parents[2]
FRAMED = ROOT / "tests" / "runtime" / "data" / "framed_create.rdis"  # an output's `frame`
EXAMPLES = [*sorted((ROOT / "examples").glob("*.rdis")), ROOT / "tests" / "golden" / "json" / "body.rdis", FRAMED]


def const(value: m.Value, type_: Type) -> m.Const:
    return m.Const(value, type_)


def var(name: str, type_: Type = Type.FLOAT, scope: Scope = Scope.PARAM) -> m.Var:
    return m.Var(name, scope, type_)


def model() -> m.Model:
    """Every element and expression form, built directly (no checker involved)."""
    speed = var("speed")
    ping = m.HookCall(m.InterfaceRef("poll"), ())
    return m.Model(
        robot=m.Robot("rover", author="A. Uthor", version="2", doc="A test rover."),
        states={
            "hits": m.StateVariable("hits", Type.INT, 0, doc="Bumper hits."),
            "gain": m.StateVariable("gain", Type.FLOAT, 1.0),
            "label": m.StateVariable("label", Type.STRING, 'say "hi"\n'),
            "armed": m.StateVariable("armed", Type.BOOL, False),
        },
        connections={
            "link": m.Connection(
                "link",
                "serial",
                57600,
                40.0,
                startup=m.HookCall(m.InterfaceRef("go"), (const(0.5, Type.FLOAT),)),
                keepalive=m.Keepalive(ping, 2.5),
                doc="The radio.",
            ),
        },
        primitives={
            "move": m.Primitive(
                "move",
                (m.Parameter("v", Type.INT),),
                m.ConnectionRef("link"),
                m.Pack(">Bh", formats.struct_layout(">Bh")),
                (const(137, Type.INT), var("v", Type.INT)),
            ),
            "sense": m.Primitive(
                "sense",
                (),
                m.ConnectionRef("link"),
                m.Format("S\n"),
                (),
                m.Regex(r"^s,(\d+)$"),
                (
                    m.PostAction(
                        m.StateRef("hits"),
                        m.FuncCall("int", (m.ReplyValue(0, Type.STRING),), Type.INT),
                    ),
                    m.PostAction(
                        m.StateRef("armed"),
                        m.UnaryOp(
                            "not",
                            m.BinaryOp(
                                "==", var("hits", Type.INT, Scope.STATE), const(0, Type.INT), Type.BOOL
                            ),
                            Type.BOOL,
                        ),
                    ),
                ),
                doc="Read the sensor.",
            ),
        },
        interfaces={
            "go": m.Interface(
                "go",
                (m.Parameter("speed", Type.FLOAT),),
                False,
                (
                    m.PrimitiveCall(
                        m.PrimitiveRef("move"),
                        (
                            m.FuncCall(
                                "round",
                                (m.BinaryOp("*", speed, const(-1000.0, Type.FLOAT), Type.FLOAT),),
                                Type.INT,
                            ),
                        ),
                        delay_ms=100.0,
                    ),
                    m.PrimitiveCall(
                        m.PrimitiveRef("move"),
                        (m.BinaryOp("**", const(-2, Type.INT), const(2, Type.INT), Type.INT),),
                        delay_ms=12.5,
                        priority=1,
                    ),
                ),
            ),
            "poll": m.Interface(
                "poll",
                (),
                True,
                (m.PrimitiveCall(m.PrimitiveRef("sense"), ()),),
                triggers=(m.OutputRef("bump"),),
            ),
        },
        adapters={
            "Range": m.Adapter("Range", (m.AdapterField("distance", Type.FLOAT, unit="m"),), standard=True),
            "Wheels": m.Adapter(
                "Wheels",
                (
                    m.AdapterField("left", Type.FLOAT, unit="m/s", ros="left", doc="Left wheel."),
                    m.AdapterField("right", Type.FLOAT),
                ),
                ros="pkg/Wheels",
                doc="Two wheel speeds.",
            ),
        },
        inputs={
            "wheels": m.DomainInput(
                "wheels",
                m.AdapterRef("Wheels"),
                m.InterfaceRef("go"),
                (
                    m.IfElse(
                        m.BinaryOp(
                            ">", var("left", scope=Scope.FIELD), var("right", scope=Scope.FIELD), Type.BOOL
                        ),
                        var("left", scope=Scope.FIELD),
                        const(math.inf, Type.FLOAT),
                        Type.FLOAT,
                    ),
                ),
            ),
        },
        outputs={
            "bump": m.DomainOutput(
                "bump",
                m.AdapterRef("Range"),
                (
                    (
                        "distance",
                        m.IfElse(
                            var("armed", Type.BOOL, Scope.STATE),
                            const(0, Type.FLOAT),
                            const(1e-05, Type.FLOAT),
                            Type.FLOAT,
                        ),
                    ),
                ),
                doc="Obstacle ahead.",
            ),
        },
    )


EXPECTED = r"""{
  "name": "rover",
  "author": "A. Uthor",
  "version": "2",
  "doc": "A test rover.",
  "stateVariables": [
    {
      "name": "hits",
      "type": "int",
      "value": "<0>",
      "doc": "Bumper hits."
    },
    {
      "name": "gain",
      "type": "float",
      "value": "<1.0>"
    },
    {
      "name": "label",
      "type": "string",
      "value": "<\"say \\\"hi\\\"\\n\">"
    },
    {
      "name": "armed",
      "type": "bool",
      "value": "<False>"
    }
  ],
  "connections": {
    "spp": [
      {
        "name": "link",
        "baud": 57600,
        "singleThreading": {
          "freqHz": 40
        },
        "startup": {
          "name": "go",
          "arguments": [
            "<0.5>"
          ]
        },
        "keepalive": {
          "name": "poll",
          "interval": 2.5,
          "arguments": []
        },
        "doc": "The radio."
      }
    ]
  },
  "primitives": [
    {
      "name": "move",
      "parameters": [
        "v"
      ],
      "parameterTypes": [
        "int"
      ],
      "connection": "link",
      "pack": ">Bh",
      "formatArgs": [
        "<137>",
        "<v>"
      ]
    },
    {
      "name": "sense",
      "parameters": [],
      "parameterTypes": [],
      "connection": "link",
      "format": "S\n",
      "formatArgs": [],
      "regex": "^s,(\\d+)$",
      "postActions": [
        "hits = int(__out__[0])",
        "armed = not hits == 0"
      ],
      "doc": "Read the sensor."
    }
  ],
  "interfaces": [
    {
      "name": "go",
      "type": "adhoc",
      "parameters": [
        "speed"
      ],
      "parameterTypes": [
        "float"
      ],
      "primitiveCalls": [
        {
          "name": "move",
          "arguments": [
            "<round(speed * -1000.0)>"
          ],
          "delay": 100,
          "priority": 0
        },
        {
          "name": "move",
          "arguments": [
            "<(-2) ** 2>"
          ],
          "delay": 12.5,
          "priority": 1
        }
      ]
    },
    {
      "name": "poll",
      "type": "periodic",
      "primitiveCalls": [
        {
          "name": "sense",
          "arguments": [],
          "delay": 0,
          "priority": 0
        }
      ],
      "triggers": "bump"
    }
  ],
  "domainAdapters": [
    {
      "name": "Wheels",
      "ros": "pkg/Wheels",
      "fields": [
        {
          "name": "left",
          "type": "float",
          "unit": "m/s",
          "ros": "left",
          "doc": "Left wheel."
        },
        {
          "name": "right",
          "type": "float"
        }
      ],
      "doc": "Two wheel speeds."
    }
  ],
  "domainInterfaces": [
    {
      "name": "wheels",
      "adapter": "Wheels",
      "parameters": [
        "left",
        "right"
      ],
      "calls": {
        "name": "go",
        "arguments": [
          "<left if left > right else float(\"inf\")>"
        ]
      }
    }
  ],
  "domainOutputs": [
    {
      "name": "bump",
      "adapter": "Range",
      "returns": {
        "distance": "<0.0 if armed else 1e-05>"
      },
      "doc": "Obstacle ahead."
    }
  ]
}
"""


def test_exact_text() -> None:
    assert to_json(model()) == EXPECTED


def test_thesis_reader_keys() -> None:
    """The members the thesis's loader reads (Appendix A) are where it looks for them."""
    doc = json.loads(to_json(model()))
    assert [c["name"] for c in doc["connections"]["spp"]] == ["link"]
    assert doc["primitives"][1]["postActions"][0].startswith("hits = ")
    call = doc["interfaces"][0]["primitiveCalls"][0]
    assert set(call) == {"name", "arguments", "delay", "priority"}
    assert doc["domainInterfaces"][0]["calls"]["name"] == "go"


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_reads_back_to_the_same_model(path: Path, tmp_path: Path) -> None:
    first = compile_path(str(path))
    assert first.model is not None, first.diagnostics.items
    text = to_json(first.model)
    (tmp_path / "meshes").mkdir()
    (tmp_path / "meshes" / "base.stl").write_bytes(b"")  # the mesh body.rdis names, beside the copy
    copy = tmp_path / (path.stem + ".json")
    copy.write_text(text, encoding="utf-8")
    second = compile_path(str(copy))
    assert second.model == first.model, second.diagnostics.items
    assert to_json(second.model) == text


@pytest.fixture(scope="module")
def seeded_builds() -> dict[str, list[subprocess.CompletedProcess[str]]]:
    """`rdisc build` of each example under hash seeds 1 and 2, one interpreter a seed (the seed is
    read when Python starts): by name, a result a seed."""
    runs = [run_rdisc_seeded([("build", path) for path in EXAMPLES], seed) for seed in ("1", "2")]
    return {path.name: [seed_runs[at] for seed_runs in runs] for at, path in enumerate(EXAMPLES)}


@pytest.mark.parametrize("path", EXAMPLES, ids=lambda p: p.name)
def test_byte_identical_under_two_hash_seeds(path: Path, seeded_builds) -> None:
    outputs = seeded_builds[path.name]
    assert outputs[0].returncode == 0, outputs[0].stderr
    assert outputs[0].stdout == outputs[1].stdout


def test_an_output_s_frame_is_written_when_given_and_each_output_s_frame_id_follows() -> None:
    """`frame LINK` is the member `frame` after the adapter; an output without one has none in
    the JSON, and its frame id is the body's base (`Model.frame_id`, which every emitter asks)."""
    compiled = compile_path(str(FRAMED))
    assert compiled.model is not None, compiled.diagnostics.items
    outputs = json.loads(to_json(compiled.model))["domainOutputs"]
    assert [list(o) for o in outputs] == [["name", "adapter", "frame", "returns", "doc"],
                                          ["name", "adapter", "returns", "doc"]]
    assert outputs[0]["frame"] == "bumper"
    assert [compiled.model.frame_id(o) for o in compiled.model.outputs.values()] == ["bumper", "base"]
    create = compile_path(str(ROOT / "examples" / "create.rdis")).model
    assert create is not None and create.frame_id(create.outputs["detect_bump"]) == ""  # no body: no frame
