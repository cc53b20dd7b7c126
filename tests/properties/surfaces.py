"""Hostile input to the surfaces that are not a description's text: the console's messages, the
recordings a replay reads, the bodies a simulation builds. The fuzzer behind
tests/security/test_surfaces_fuzz.py (a few of each in the suite) and `benchmarks/fuzz.py
--surface console|replay|sim` (long runs).

Each case is made from (seed, index) alone, in the process that runs it, so a finding is
reproduced by its numbers: `case(surface, seed, index)`, then `run(surface, case)`.

- console: a page's message, as the WebSocket hands it to `Console.call` (text or bytes): a
  well-formed call of an example's input, interface or primitive, changed the way description
  mutants are (values replaced by hostile JSON, tokens and characters), or a hostile message
  outright (deep nesting, huge numbers, non-ASCII digits, not JSON). The console is a real one
  on the example's plans, its robot on a port whose device answers each write with bytes of
  the case's own; a call must end as a result, never raise.
- replay: an MCAP file: a recording the recorder made of a session of an example, its records
  changed (a run's JSON, the metadata, a topic, a schema, a message's bytes), written again
  with any compression, and sometimes its bytes changed after; it goes where `rdisc replay`
  sends it (read, replayed, compared) and may only end in the errors the command turns into
  a line and an exit status.
- sim: an example's body section (its links, joints, transmissions) changed as a description
  mutant is, checked, and when it checks, simulated: MuJoCo loads the body and the robot runs
  its schedule for a few timesteps; only diagnostics and SimulationError may end it.
"""

from __future__ import annotations

import io
import json
import random
import re
import struct
import zlib
from functools import cache
from pathlib import Path
from typing import Any

from mutants import REPO, _mutate_json, mutate

EXAMPLES = sorted((REPO / "examples").glob("*.rdis"))
BODIES = [REPO / "examples" / "arm.rdis", REPO / "examples" / "create2.rdis", REPO / "tests" / "sim" / "sim_arm.rdis",
          REPO / "tests" / "golden" / "json" / "body.rdis"]
SURFACES = ("console", "replay", "sim")
SIM_STEPS = 20  # timesteps a simulated body runs

_HOSTILE_VALUES = ["1e400", "inf", "-inf", "nan", "\u0663\u0663", "9" * 5000, "0x" + "f" * 40, "1" * 25, "-0",
                   "[1, 2, 3]", "[" * 40, "00 ff", "zz", "\ud800", "\u2028", "", " ", "true", "1_000", "0b101",
                   "1e-400", "٣", "１", "[1e400]", ",", "[,]", "x" * 70_000]


# ---- the examples, compiled once a process -------------------------------------------------------------


@cache
def _compiled(path: Path) -> Any:
    from rdisc.compile import compile_path

    c = compile_path(str(path))
    assert c.model is not None and not c.diagnostics.has_errors(), path
    return c.model


@cache
def _device(path: Path) -> Any:
    from rdisc.runtime.device import Description

    return Description(_compiled(path)).device


def _calls(device: Any) -> list[dict[str, Any]]:
    """A well-formed call of each input, interface and primitive (values as a form gives them)."""
    calls = []
    for kind, plans in (("input", device.inputs), ("interface", device.interfaces), ("primitive", device.primitives)):
        for name, plan in plans.items():
            params = plan.fields if kind == "input" else plan.params
            calls.append({"kind": kind, "name": name, "values": {p.name: _text(p) for p in params}})
    return calls


def _text(param: Any) -> str:
    item = "00" if param.kind is bytes else "true" if param.kind is bool else "a" if param.kind is str else "1"
    return item if param.size is None else "[" + ", ".join([item] * max(1, min(param.size or 1, 8))) + "]"


class _Answers:
    """A device behind the fake port that answers each write with a few bytes of the case's."""

    def __init__(self, rng: random.Random) -> None:
        self.rng = rng

    def answer(self, request: bytes) -> bytes:
        kind = self.rng.randrange(4)
        if kind == 0:
            return b""
        if kind == 1:
            return request  # an echo
        return bytes(self.rng.randrange(256) for _ in range(self.rng.randrange(40)))

    def listen(self) -> bytes:
        return b""


def _no_sleep(seconds: float) -> None:
    """A delay not waited for."""


def _ports(device: Any, rng: random.Random) -> dict[str, Any]:
    from tests.support.ports import ScriptedPort

    return {name: ScriptedPort(device=_Answers(rng), timeout=0.0) for name in device.connections}


# ---- the console ---------------------------------------------------------------------------------------


@cache
def _console(path: Path) -> tuple[Any, list[Any]]:
    """A console of the example and its robot's ports, the robot open (no threads: the console's
    calls make the writes)."""
    from rdisc.console.server import Console

    robot, ports = _opened(_device(path), random.Random(0))
    return Console(robot, "<html></html>"), ports


def _opened(device: Any, rng: random.Random) -> tuple[Any, list[Any]]:
    """A robot of the device open on fake ports whose device answers with the case's bytes, its
    delays not waited for; its startup hooks are not run (a device of random bytes seldom answers
    them as they expect, and the robot would not open)."""
    from rdisc import engine

    robot = engine.Robot(device, timeout=0.001)
    robot._sleep = _no_sleep
    robot.startup = lambda: None  # type: ignore[method-assign]
    ports = _ports(device, rng)
    robot.open(ports, threads=False)
    return robot, list(ports.values())


def console_case(seed: int, index: int) -> tuple[str, str | bytes]:
    """(the example's path, a page's message)."""
    rng = random.Random(f"console:{seed}:{index}")
    path = rng.choice(EXAMPLES)
    calls = _calls(_device(path))
    call = dict(rng.choice(calls), id=index)
    kind = rng.randrange(6)
    if kind == 0:  # a value replaced by a hostile text, the others kept
        values = dict(call["values"])
        if values:
            values[rng.choice(sorted(values))] = rng.choice(_HOSTILE_VALUES)
        message = json.dumps(dict(call, values=values), ensure_ascii=rng.random() < 0.5)
    elif kind in (1, 2):  # any member replaced by any JSON value
        message = _mutate_json(json.dumps(call), rng)
    elif kind == 3:  # tokens, lines and characters
        message = mutate(json.dumps(call, indent=1), rng, [json.dumps(c) for c in calls[:8]], rng.choice([1, 2, 3]))
    elif kind == 4:  # nesting
        depth = rng.choice([31, 32, 33, 100, 60_000])
        opening, closing = rng.choice([("[", "]"), ('{"a":', "}")])
        message = json.dumps(call)[:-1] + ', "values": ' + opening * depth + "1" + closing * depth + "}"
    else:
        message = rng.choice(['"call"', "null", "[]", "1e400", "{", "", "\x00", '{"kind": "input"}', "{}" * 1000,
                              '{"id": ' + "9" * 5000 + "}", '{"kind": "interface", "name": 5}'])
    if rng.random() < 0.15:
        return str(path), message.encode("utf-8", "surrogatepass")
    return str(path), message


def run_console(case: tuple[str, str | bytes]) -> None:
    """The message through the console's call, as a page's WebSocket hands it on; the reply sent back."""
    path, message = case
    console, ports = _console(Path(path))
    for port in ports:  # the device answers as this case's, whichever cases ran before it
        port.device.rng = random.Random(zlib.crc32(message if isinstance(message, bytes) else
                                                   message.encode("utf-8", "surrogatepass")))
    reply = console.call(message)
    if not (isinstance(reply, dict) and reply.get("type") == "result" and isinstance(reply.get("ok"), bool)):
        raise AssertionError(f"the console answered {reply!r}")
    json.dumps(reply)  # what the page is sent
    for port in ports:  # what the fake ports keep of a long session (a worker runs thousands of cases)
        port.events.clear()
        port.written.clear()
        port.given.clear()


# ---- recordings ----------------------------------------------------------------------------------------


@cache
def _seed_recording(path: Path, seed: int) -> bytes:
    """A recording the recorder makes of a session of the example: each call it has, made once
    with a form's values where they fit, and each periodic interface run once."""
    from rdisc import engine

    device = _device(path)
    rng = random.Random(f"recording:{path.name}:{seed}")
    output = io.BytesIO()
    robot = engine.Robot(device, timeout=0.001)
    recorder = engine.Recorder(robot, output, {})
    robot._sleep = _no_sleep
    robot.startup = lambda: None  # type: ignore[method-assign]
    robot.open(_ports(device, rng), threads=False)
    try:
        for call in _calls(device)[:24]:
            try:
                values = engine.call_values(device, call["kind"], call["name"], call["values"])
            except (engine.RdisError, TypeError, ValueError, KeyError):
                continue
            recorder.call(call["kind"], call["name"], values)
            try:
                engine.make_call(robot, call["kind"], call["name"], values)
            except engine.RdisError as err:
                recorder.error(err)
        for connection in device.connections.values():
            for interface in connection.periodic[:3]:
                recorder.run(connection.name, "periodic", interface.name)
                try:
                    robot.call_interface(interface.name)
                except engine.RdisError as err:
                    recorder.error(err)
    finally:
        robot.close()
        recorder.finish()
    return output.getvalue()


def _records(data: bytes) -> tuple[dict[str, str], list[Any], list[Any], list[Any]]:
    """The `rdisc` metadata, schemas, channels and messages of a recording (chunks opened)."""
    from mcap.records import Channel, Message, Metadata, Schema
    from mcap.stream_reader import StreamReader

    metadata: dict[str, str] = {}
    schemas, channels, messages = [], [], []
    for record in StreamReader(io.BytesIO(data)).records:
        if isinstance(record, Schema):
            schemas.append(record)
        elif isinstance(record, Channel):
            channels.append(record)
        elif isinstance(record, Message):
            messages.append(record)
        elif isinstance(record, Metadata) and record.name == "rdisc":
            metadata = dict(record.metadata)
    return metadata, list({s.id: s for s in schemas}.values()), list({c.id: c for c in channels}.values()), messages


def _cdr_text(text: str) -> bytes:
    data = text.encode("utf-8", "surrogatepass")
    return b"\x00\x01\x00\x00" + struct.pack("<I", len(data) + 1) + data + b"\x00"


def _text_of(data: bytes) -> str | None:
    if len(data) < 9:
        return None
    (size,) = struct.unpack_from("<I", data, 4)
    return data[8:8 + size - 1].decode("utf-8", "replace") if 8 + size <= len(data) else None


def _mutate_recording(data: bytes, rng: random.Random) -> bytes:
    """The recording's records changed in one to four places, then written again."""
    from mcap.writer import CompressionType, Writer

    metadata, schemas, channels, messages = _records(data)
    texts = [json.dumps(v) for v in ({"call": "input", "name": "x", "values": {}}, {"periodic": "p", "connection": "c"})]
    for _ in range(rng.randint(1, 4)):
        action = rng.randrange(9)
        if action == 0 and messages:  # a run's (or a JSON output's) text changed
            runs = [m for m in messages if _text_of(m.data) is not None]
            if runs:
                m = rng.choice(runs)
                text = _text_of(m.data) or ""
                try:
                    changed = _mutate_json(text, rng) if rng.random() < 0.6 else mutate(text, rng, texts, 2)
                except ValueError:
                    changed = mutate(text, rng, texts, 2)
                m.data = _cdr_text(changed)
        elif action == 1 and messages:  # a message's bytes changed
            m = rng.choice(messages)
            body = bytearray(m.data)
            for _ in range(rng.randint(1, 4)):
                if body:
                    body[rng.randrange(len(body))] = rng.randrange(256)
            if rng.random() < 0.3:
                body = body[: rng.randrange(len(body) + 1)]
            m.data = bytes(body)
        elif action == 2:  # the metadata
            key = rng.choice(["settings", "timeout", "robot", "other"])
            metadata[key] = rng.choice(['{"a": 1}', "[]", "1e400", "-1", "0", "null", "{", '{"x": [1, {"y": 2}]}',
                                        "[" * 3000 + "]" * 3000, '"' + "a" * 100 + '"', "nan", "Infinity"])
            if rng.random() < 0.1:
                metadata.clear()
        elif action == 3 and channels:  # a channel's topic
            c = rng.choice(channels)
            c.topic = rng.choice(["/rdisc/runs", "/rosout", "/", "", "/a/b/c/d/e", "/rdisc/x/write", "/rdisc/x/read",
                                  "/rdisc/x/lines", c.topic + "x", "/set_velocity"])
        elif action == 4 and channels and schemas:  # a channel's schema
            c = rng.choice(channels)
            c.schema_id = rng.choice([s.id for s in schemas] + [0, 99])
        elif action == 5 and schemas:  # a schema's text
            s = rng.choice(schemas)
            text = s.data.decode("utf-8", "replace")
            s.data = mutate(text, rng, [t.data.decode("utf-8", "replace") for t in schemas], 2).encode(
                "utf-8", "surrogatepass")
        elif action == 6 and messages:  # messages duplicated, dropped, swapped, retimed
            i, j = rng.randrange(len(messages)), rng.randrange(len(messages))
            which = rng.randrange(4)
            if which == 0:
                messages.insert(i, messages[j])
            elif which == 1:
                del messages[i]
            elif which == 2:
                messages[i], messages[j] = messages[j], messages[i]
            else:
                messages[i].log_time = rng.choice([0, 2**63, 2**64 - 1, messages[j].log_time])
        elif action == 7 and messages:  # many copies of one message
            m = rng.choice(messages)
            messages.extend([m] * rng.choice([100, 1000, 5000]))
        elif action == 8 and channels:  # the encoding
            rng.choice(channels).message_encoding = rng.choice(["json", "", "cdr", "ros1"])
    out = io.BytesIO()
    writer = Writer(out, compression=rng.choice([CompressionType.ZSTD, CompressionType.LZ4, CompressionType.NONE]),
                    chunk_size=rng.choice([512, 4096, 1 << 20]))
    writer.start("ros2", "fuzz")
    if metadata or rng.random() < 0.5:
        writer.add_metadata("rdisc", metadata)
    known = {s.id: writer.register_schema(s.name, s.encoding, s.data) for s in schemas}
    ids = {c.id: writer.register_channel(c.topic, c.message_encoding, known.get(c.schema_id, c.schema_id))
           for c in channels}
    for m in messages:
        writer.add_message(ids.get(m.channel_id, 1), m.log_time, m.data, m.publish_time, m.sequence)
    writer.finish()
    return out.getvalue()


def _mutate_bytes(data: bytes, rng: random.Random) -> bytes:
    """The file's bytes changed: flipped, cut short, a range repeated, random bytes let in."""
    body = bytearray(data)
    for _ in range(rng.randint(1, 3)):
        action = rng.randrange(4)
        i = rng.randrange(len(body) + 1)
        if action == 0 and body:
            body[min(i, len(body) - 1)] ^= 1 << rng.randrange(8)
        elif action == 1:
            del body[i:]
        elif action == 2:
            j = min(len(body), i + rng.randrange(1, 64))
            body[i:i] = body[i:j] * rng.randint(1, 4)
        else:
            body[i:i] = bytes(rng.randrange(256) for _ in range(rng.randint(1, 16)))
    return bytes(body)


def replay_case(seed: int, index: int) -> tuple[str, bytes]:
    """(the example's path, a recording's bytes)."""
    rng = random.Random(f"replay:{seed}:{index}")
    path = rng.choice(EXAMPLES)
    data = _seed_recording(path, seed % 4)
    kind = rng.randrange(5)
    if kind < 3:
        data = _mutate_recording(data, rng)
    if kind >= 2:
        data = _mutate_bytes(data, rng)
    return str(path), data


def run_replay(case: tuple[str, bytes]) -> None:
    """What `rdisc replay` does with the file (rdisc/cli/replay.py): read it, replay it, compare; the
    errors that command turns into a line and an exit status end it, anything else is a finding."""
    from rdisc import engine
    from rdisc.runtime.replay import RecordingError, differences, read_recording, replay

    path, data = case
    device = _device(Path(path))
    try:
        recorded = read_recording(io.BytesIO(data))
    except RecordingError:
        return
    try:
        replayed = replay(recorded, device)
    except (engine.RdisError, TypeError, ValueError):
        return
    "\n".join(differences(recorded, replayed, device)).encode("utf-8")


# ---- bodies --------------------------------------------------------------------------------------------

_BODY = re.compile(r"^(?:///[^\n]*\n)*(?:link|joint|transmission) ", re.MULTILINE)


def sim_case(seed: int, index: int) -> tuple[str, str]:
    """(a name for the file, a description whose body section is changed)."""
    rng = random.Random(f"sim:{seed}:{index}")
    path = rng.choice(BODIES)
    text = path.read_text(encoding="utf-8")
    start = _BODY.search(text)
    assert start is not None, path
    head, body = text[: start.start()], text[start.start():]
    others = [p.read_text(encoding="utf-8") for p in BODIES]
    others = [o[m.start():] for o in others if (m := _BODY.search(o)) is not None]
    return path.name, head + mutate(body, rng, others, rng.choice([1, 1, 2, 3, 5]))


def run_sim(case: tuple[str, str], folder: Path) -> None:
    """The description checked; its body emitted (URDF, MJCF) and simulated for SIM_STEPS timesteps
    with its robot's schedule running; only a diagnostic or SimulationError may end it."""
    from rdisc import engine
    from rdisc.compile import compile_path
    from rdisc.emit.mjcf import to_mjcf
    from rdisc.runtime.device import Description
    from rdisc.sim import Simulation, SimulationError

    name, text = case
    path = folder / name
    path.write_text(text, encoding="utf-8", errors="surrogatepass")
    c = compile_path(str(path))
    if c.model is None or c.diagnostics.has_errors() or not c.model.links:
        return
    to_mjcf(c.model).encode("utf-8")
    try:
        simulation = Simulation(c.model, seed=1)
    except SimulationError:
        return
    robot = engine.Robot(Description(c.model).device, timeout=0.01)
    try:
        robot.open(sim=simulation)
        robot.run_for(SIM_STEPS * simulation.physics.opt.timestep)
    except engine.RdisError:
        pass
    finally:
        robot.close()


# ---- one entry for both callers -------------------------------------------------------------------------


def case(surface: str, seed: int, index: int) -> Any:
    return {"console": console_case, "replay": replay_case, "sim": sim_case}[surface](seed, index)


def run(surface: str, made: Any, folder: Path) -> None:
    if surface == "console":
        run_console(made)
    elif surface == "replay":
        run_replay(made)
    else:
        run_sim(made, folder)


def shown(surface: str, made: Any) -> str:
    """A case as the report shows it (a recording's first bytes in hex)."""
    where, what = made
    if isinstance(what, bytes) and surface == "replay":
        return f"{where}: {len(what)} bytes: {what[:600].hex(' ')}"
    return f"{where}:\n{what[:2000]!r}" if isinstance(what, bytes) else f"{where}:\n{what[:2000]}"


def size(made: Any) -> int:
    return len(made[1])
