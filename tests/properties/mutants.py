"""Mutated descriptions, and the whole pipeline run on each: the fuzzer behind
test_mutants.py (a modest run in the suite) and benchmarks/fuzz.py (long runs).

A mutant is an example or test description changed in a few places, at the level of
tokens and lines: a number replaced by an extreme one (10 ** 400, 1e308, 1114112, -5),
a string by a hostile one (a lone surrogate, non-ASCII digits, a line separator, NUL),
lines deleted, duplicated or swapped, a line of another description spliced in,
characters flipped; JSON mutants are the canonical JSON of a description, changed
the same way. Each mutant goes through everything a user can make rdisc do with a
file: check, the diagnostics rendered as text and as LSP JSON and encoded as UTF-8,
canonical JSON and back, `dump`, the Python driver, the ROS node and the runtime's
plans. Anything raised that is not a diagnostic is a finding, named by the place in
rdisc it came from.
"""

from __future__ import annotations

import json
import random
import re
import traceback
from dataclasses import dataclass
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
SEEDS = sorted([*REPO.glob("examples/*.rdis"), *REPO.glob("tests/runtime/data/*.rdis"),
                *REPO.glob("tests/semantics/cases/*.rdis")])

NUMBERS = ["10 ** 400", "1e308", "1e300", "-1e308", "2 ** 1100", "1e39", "65520.0", "1114112", "-5", "0", "-0.0",
           "2 ** 63", "2 ** 64", "-(2 ** 63) - 1", "1 << 1000", "99999999999999999999", "0.1", "3"]
STRINGS = [r'"\ud800"', r'"\udfff x"', '"\u0661B"', '"B\u2028"', '"B "', r'"\0"', '"x" * 1000', '""',
           r'"{:c}"', r'"{:>99999}"', '"crc16-buypass"', '"crc-99"', r'"\xFF\xFF"', '"<4s"', '"x"',
           '"' + "a" * 300 + '"', r'"\u0000/x"']
WORDS = ["delay", "timeout", "every", "length", "field", "checksum", "payload", "header", "frame", "reply",
         "skip unmatched", "periodic", "triggers", "in", "..", "bytes", "float", "int", "import", "ms", "**", "<<"]
_TOKEN = re.compile(r'r?"(?:[^"\\\n]|\\.)*"|\d[\w.]*|[A-Za-z_]\w*|\*\*|<<|>>|\.\.|\S')


@dataclass(frozen=True)
class Mutant:
    seed: str  # the seed's path, relative to the repository
    text: str
    suffix: str  # ".rdis" or ".json"


def seed_texts() -> dict[str, str]:
    return {str(p.relative_to(REPO)): p.read_text(encoding="utf-8") for p in SEEDS}


def mutate(text: str, rng: random.Random, others: list[str], edits: int) -> str:
    """`text` with `edits` random edits, each at the level of tokens, lines or characters."""
    for _ in range(edits):
        text = rng.choice(_EDITS)(text, rng, others)
    return text


def _tokens(text: str) -> list[re.Match[str]]:
    return list(_TOKEN.finditer(text))


def _replace_token(text: str, rng: random.Random, kind: str) -> str:
    tokens = [t for t in _tokens(text) if (t.group()[:1].isdigit() if kind == "number" else
                                           t.group().endswith('"') if kind == "string" else True)]
    if not tokens:
        return text
    t = rng.choice(tokens)
    new = rng.choice(NUMBERS if kind == "number" else STRINGS if kind == "string" else WORDS + NUMBERS)
    return text[: t.start()] + new + text[t.end():]


def _lines(text: str, rng: random.Random, others: list[str]) -> str:
    lines = text.split("\n")
    i, j = rng.randrange(len(lines)), rng.randrange(len(lines))
    action = rng.randrange(4)
    if action == 0:
        del lines[i]
    elif action == 1:
        lines.insert(i, lines[j])
    elif action == 2:
        lines[i], lines[j] = lines[j], lines[i]
    else:
        other = rng.choice(others).split("\n")
        lines.insert(i, rng.choice(other))
    return "\n".join(lines)


def _delete_token(text: str, rng: random.Random, others: list[str]) -> str:
    tokens = _tokens(text)
    if not tokens:
        return text
    t = rng.choice(tokens)
    return text[: t.start()] + text[t.end():]


def _flip(text: str, rng: random.Random, others: list[str]) -> str:
    if not text:
        return text
    i = rng.randrange(len(text))
    return text[:i] + rng.choice('"\\{}()[]:;,.#/*-+0\n\x00\u00e9\u2028') + text[i + 1:]


_EDITS = [
    lambda t, r, o: _replace_token(t, r, "number"),
    lambda t, r, o: _replace_token(t, r, "number"),
    lambda t, r, o: _replace_token(t, r, "string"),
    lambda t, r, o: _replace_token(t, r, "string"),
    lambda t, r, o: _replace_token(t, r, "any"),
    _lines,
    _delete_token,
    _flip,
]


def mutants(seed: int, count: int) -> list[Mutant]:
    """`count` mutants, the same for the same `seed`; about one in six is JSON."""
    rng = random.Random(seed)
    texts = seed_texts()
    names = sorted(texts)
    others = [texts[n] for n in names]
    out = []
    for _ in range(count):
        name = rng.choice(names)
        edits = rng.choice([1, 1, 2, 3, 5])
        if rng.randrange(6) == 0:
            canonical = _canonical(texts[name])
            if canonical is not None:
                out.append(Mutant(name, _mutate_json(canonical, rng), ".json"))
                continue
        out.append(Mutant(name, mutate(texts[name], rng, others, edits), ".rdis"))
    return out


_CANONICAL: dict[str, str | None] = {}


def _canonical(text: str) -> str | None:
    """The canonical JSON of a seed that checks, else None (kept: seeds are few)."""
    if text not in _CANONICAL:
        import tempfile

        from rdisc.compile import compile_path
        from rdisc.emit.canonical import to_json

        with tempfile.TemporaryDirectory() as folder:
            path = Path(folder) / "seed.rdis"
            path.write_text(text, encoding="utf-8")
            c = compile_path(str(path))
        _CANONICAL[text] = to_json(c.model) if c.model is not None and not c.diagnostics.has_errors() else None
    return _CANONICAL[text]


_JSON_VALUES = [10 ** 400, 1e308, -5, 1114112, 2 ** 64, -1, 0, 1e30, "\ud800", "\u0661B", "B\u2028", "", "x" * 300,
                [1, 99], [0, 1e30], [-5, 2], None, True, {"a": 1}, []]


def _mutate_json(text: str, rng: random.Random) -> str:
    """The JSON with one to three values replaced (numbers, strings, lists, whole members)."""
    document = json.loads(text)
    places: list[tuple[object, object]] = []

    def walk(node: object) -> None:
        if isinstance(node, dict):
            for key, value in node.items():
                places.append((node, key))
                walk(value)
        elif isinstance(node, list):
            for i, value in enumerate(node):
                places.append((node, i))
                walk(value)

    walk(document)
    for _ in range(rng.randint(1, 3)):
        if not places:
            break
        holder, key = rng.choice(places)
        holder[key] = rng.choice(_JSON_VALUES)  # type: ignore[index]
    return json.dumps(document, ensure_ascii=True)


# ---- the pipeline -------------------------------------------------------------------------------------


def run_pipeline(path: Path) -> None:
    """Everything a user can make rdisc do with the file at `path`; raises what rdisc raises."""
    from rdisc.compile import compile_path
    from rdisc.diagnostics.lsp import to_lsp
    from rdisc.diagnostics.text import render_plain
    from rdisc.emit.canonical import to_json
    from rdisc.emit.dump import dump
    from rdisc.emit.mjcf import to_mjcf
    from rdisc.emit.python import to_python
    from rdisc.emit.ros import to_ros
    from rdisc.emit.sdf import to_sdf
    from rdisc.emit.urdf import to_urdf
    from rdisc.runtime.device import Description

    c = compile_path(str(path))
    render_plain(c.diagnostics.items, c.sources).encode("utf-8")
    json.dumps(to_lsp(c.diagnostics.items, c.sources), ensure_ascii=False).encode("utf-8")
    if c.model is None or c.diagnostics.has_errors():
        return
    canonical = to_json(c.model)
    dump(c.model).encode("utf-8")
    to_python(c.model, path.name, sources=c.sources).encode("utf-8")
    to_ros(c.model, path.name, sources=c.sources).encode("utf-8")
    Description(c.model)
    if c.model.links:  # the body, in every format; MuJoCo must take what rdisc accepted
        to_urdf(c.model, path.name).encode("utf-8")
        to_sdf(c.model, path.name).encode("utf-8")
        _mujoco_loads(to_mjcf(c.model))
    back = path.with_name(path.stem + ".back.json")
    back.write_text(canonical, encoding="utf-8")
    again = compile_path(str(back))
    assert again.model is not None and not again.diagnostics.has_errors(), render_plain(again.diagnostics.items,
                                                                                        again.sources)


def _mujoco_loads(mjcf: str) -> None:
    """MuJoCo compiles the model (when installed): a body rdisc accepts is one it can simulate."""
    try:
        import mujoco
    except ImportError:
        return
    mujoco.MjModel.from_xml_string(mjcf)


def finding(error: BaseException) -> str:
    """Where in rdisc an exception came from: `Type at rdisc/file.py:line` (the innermost frame of rdisc)."""
    frames = [f for f in traceback.extract_tb(error.__traceback__) if "/rdisc/" in f.filename.replace("\\", "/")]
    where = "?"
    if frames:
        f = frames[-1]
        where = f"rdisc/{f.filename.replace(chr(92), '/').split('/rdisc/')[-1]}:{f.lineno}"
    return f"{type(error).__name__} at {where}"
