"""Whatever the input, rdisc answers with diagnostics, never with an exception.

Thousands of damaged versions of real descriptions (the examples and the
standard adapters; the canonical JSON of the examples) go through the whole
pipeline (`compile_path`: read, parse or import, resolve, check, budget) and
both renderings. Every diagnostic must have a registered code and a place inside
the file it names. Hypothesis runs derandomised, so CI sees the same inputs on
every run; RDISC_FUZZ_SCALE=N tries N times as many (a deeper search, after a
change to the parser, the importer or the checker). A handful of giant inputs
check the limits on size and nesting; what each may cost is a multiple of a real
description's check, both in CPU time of the test's own thread, so a busy or a
slow machine does not change the verdict.
"""

from __future__ import annotations

import json
import random
import re
import time
import traceback
from pathlib import Path

import pytest
from conftest import FUZZ_SCALE, fuzz_examples
from hypothesis import HealthCheck, given, reject, settings
from hypothesis import strategies as st

from rdisc.compile import Compilation, compile_module, compile_path
from rdisc.diagnostics import Diagnostics, Severity
from rdisc.diagnostics.codes import CODES
from rdisc.diagnostics.lsp import to_lsp
from rdisc.diagnostics.text import render_plain
from rdisc.source import Sources

pytestmark = pytest.mark.long  # started before the other files (tests/conftest.py)

REPO = Path(__file__).resolve().parents[2]
BODY = REPO / "tests" / "golden" / "json" / "body.rdis"  # every kind of link, joint and transmission
SEED_PATHS = sorted((REPO / "examples").glob("*.rdis")) + [REPO / "stdlib" / "adapters.rdis", BODY]
SEEDS = [p.read_text(encoding="utf-8") for p in SEED_PATHS]

FUZZ = settings(
    deadline=None,
    derandomize=True,
    database=None,
    print_blob=True,
    suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large, HealthCheck.large_base_example],
)

# Pieces of RDIS and of things that are not RDIS: delimiters, keywords, operators,
# literals at the limits, Python escape hatches, and characters that upset renderers.
TOKENS = [
    "{", "}", "(", ")", "[", "]", ",", ":", "=", "->", '"', 'r"', "\\", "///", "#", "\n", "\r", "\t", " ",
    "robot", "state", "connection", "primitive", "interface", "adapter", "input", "output", "import",
    "on", "pack", "format", "unpack", "regex", "periodic", "adhoc", "triggers", "delay", "priority",
    "every", "ms", "s", "Hz", "baud", "threading", "single", "startup", "terminate", "keepalive",
    "serial", "if", "else", "and", "or", "not", "True", "False", "out", "out[0]", "out[99]",
    "int", "float", "bool", "string", "round(", "clamp(", "abs(", "**", "<<", ">>", "//", "%", "~", "-",
    "((((((((((", "))))))))))", "-" * 150, "(" * 200, "not " * 130, "~" * 140,
    "0", "-1", "1e308", "1e999", "0x", "0b2", "1__0", "007", "9" * 70, "3.5", ".5e-3", "1_000",
    '"{0.__class__}"', '"{!r}"', '"{:>999999999}"', '"{"', '"}"', '"\\q"', '"\\x4"', '"\\uZZZZ"',
    'r"(\\d+"', '"%s"', '">Bz"', '"P"', '"999999999B"', '"@"',
    "__import__('os')", "_x", "x.y", "eval(", "lambda", "[x for x in y]",
    "link", "joint", "transmission", "visual", "collision", "mesh(", "box(", "mass", "inertia", "axis", "limit",
    "command", "measure", "to", "from", "raw", "->", "..", "[0, 0, 0]", "[1e308, 1, 1]",
    "\x00", "\x1b[31m", "\u202e", "\u200b", "\ufeff", "\u0301", "\U0001F916", "\ud7ff", "\u2028", "\x85",
    "é", "字", "\uffff",
]


# Crashes found by these properties, each with an xfail test below (by exception type and
# the function that raised it). Only `test_expression_swaps_round_trip` passes them over,
# so that it keeps looking for others; delete an entry when its test passes.
KNOWN_CRASHES: list[tuple[type[BaseException], str]] = []


def _known(exc: BaseException) -> bool:
    where = traceback.extract_tb(exc.__traceback__)[-1].name
    return any(isinstance(exc, kind) and where == name for kind, name in KNOWN_CRASHES)


def check(path: Path, *, tolerate_known: bool = False) -> Compilation:
    """Compile, render both ways, and check every diagnostic's code and place."""
    try:
        c = compile_path(str(path))
    except Exception as exc:
        if tolerate_known and _known(exc):
            reject()
        raise
    items = c.diagnostics.items
    for d in items:
        assert d.code in CODES, d
        assert d.severity is (Severity.ERROR if d.code.startswith("E") else Severity.WARNING), d
        assert isinstance(d.message, str) and d.message.strip(), d
        assert d.span is not None, d  # every diagnostic has a place, if only the file
        if d.code == "E006":  # an unreadable file: its name, no text to point into
            assert d.span.path not in c.sources and d.span.start == d.span.end == 0, d
            continue
        for span in [d.span] + [label.span for label in d.labels]:
            assert span.path in c.sources, d
            assert 0 <= span.start <= span.end <= len(c.sources[span.path].text), d
    assert (c.model is None) == c.diagnostics.has_errors()
    ordered = c.diagnostics.sorted()
    text = render_plain(ordered, c.sources)
    assert all(f"[{d.code}]" in text for d in items)
    json.dumps(to_lsp(ordered, c.sources))
    return c


def check_import(path: Path) -> None:
    """What `rdisc import` does in-process: read the JSON, check it, print the source
    (written whenever the JSON could be read, errors or not)."""
    from rdisc.json_import.document import read
    from rdisc.syntax.printer import print_module

    diagnostics, sources = Diagnostics(), Sources()
    text = path.read_text(encoding="utf-8")
    sources.add(str(path), text)
    module = read(str(path), text, diagnostics)
    if module is None:
        assert diagnostics.has_errors()
        return
    c = compile_module(module, diagnostics, sources)
    render_plain(c.diagnostics.sorted(), c.sources)
    printed = path.with_suffix(".printed.rdis")
    printed.write_text(print_module(module), encoding="utf-8")
    again = check(printed)
    if c.model is not None:
        assert again.model is not None, render_plain(again.diagnostics.sorted(), again.sources)


@pytest.fixture(scope="module")
def workdir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return tmp_path_factory.mktemp("fuzz")


# -- text mutations ------------------------------------------------------------------

edit = st.tuples(
    st.sampled_from(["replace", "delete", "insert-token", "insert-text", "duplicate", "swap"]),
    st.floats(0, 1),
    st.floats(0, 1),
    st.sampled_from(TOKENS),
    st.text(max_size=12),
)


def mutate(text: str, edits) -> str:
    for kind, a, b, token, junk in edits:
        n = len(text)
        i, j = sorted((int(a * n), int(b * n)))
        j = min(j, i + 200)
        if kind == "replace":
            text = text[:i] + (junk[:1] or token) + text[i + 1:]
        elif kind == "delete":
            text = text[:i] + text[j:]
        elif kind == "insert-token":
            text = text[:i] + token + text[i:]
        elif kind == "insert-text":
            text = text[:i] + junk + text[i:]
        elif kind == "duplicate":
            text = text[:j] + text[i:j] + text[j:]
        else:  # swap two pieces
            text = text[j:] + text[i:j] + text[:i]
    return text


@settings(FUZZ, max_examples=fuzz_examples(75))
@given(seed=st.integers(0, len(SEEDS) - 1), edits=st.lists(edit, min_size=1, max_size=6))
def test_mutated_descriptions(workdir: Path, seed: int, edits) -> None:
    path = workdir / "mutated.rdis"
    path.write_text(mutate(SEEDS[seed], edits), encoding="utf-8")
    check(path)


@settings(FUZZ, max_examples=fuzz_examples(30))
@given(
    seeds=st.lists(st.integers(0, len(SEEDS) - 1), min_size=2, max_size=3),
    cuts=st.lists(st.tuples(st.floats(0, 1), st.floats(0, 1)), min_size=3, max_size=3),
)
def test_spliced_descriptions(workdir: Path, seeds, cuts) -> None:
    """Pieces of several files glued together at arbitrary places."""
    parts = []
    for seed, (a, b) in zip(seeds, cuts):
        text = SEEDS[seed]
        i, j = sorted((int(a * len(text)), int(b * len(text))))
        parts.append(text[i:j])
    path = workdir / "spliced.rdis"
    path.write_text("".join(parts), encoding="utf-8")
    check(path)


@settings(FUZZ, max_examples=fuzz_examples(50))
@given(
    seed=st.integers(0, len(SEEDS) - 1),
    flips=st.lists(st.tuples(st.floats(0, 1), st.integers(1, 255)), min_size=1, max_size=4),
    insert=st.binary(max_size=8),
)
def test_byte_flips(workdir: Path, seed: int, flips, insert: bytes) -> None:
    """Flipped bits may leave UTF-8 (E006) or land in the middle of a token."""
    data = bytearray(SEEDS[seed].encode("utf-8"))
    for at, mask in flips:
        data[min(int(at * len(data)), len(data) - 1)] ^= mask
    at = int(flips[0][0] * len(data))
    data[at:at] = insert
    path = workdir / "flipped.rdis"
    path.write_bytes(bytes(data))
    check(path)


@settings(FUZZ, max_examples=fuzz_examples(30))
@given(seed=st.integers(0, len(SEEDS) - 1), tokens=st.lists(st.sampled_from(TOKENS), min_size=1, max_size=40))
def test_token_soup_after_a_good_prefix(workdir: Path, seed: int, tokens) -> None:
    """Half a real file, then a stream of tokens in any order."""
    text = SEEDS[seed]
    path = workdir / "soup.rdis"
    path.write_text(text[: len(text) // 2] + " ".join(tokens), encoding="utf-8")
    check(path)


@pytest.mark.parametrize("seed", range(len(SEEDS)), ids=[p.name for p in SEED_PATHS])
def test_truncated_at_a_sample_of_lengths(workdir: Path, seed: int) -> None:
    """Truncation at one length in 179 (in 179 / RDISC_FUZZ_SCALE), plus every length of a
    60-character region."""
    text = SEEDS[seed]
    region = text.index("primitive") if "primitive" in text else len(text) // 2
    step = max(1, round(179 / FUZZ_SCALE))
    lengths = sorted(set(range(0, len(text) + 1, step)) | set(range(region, min(region + 60, len(text)))))
    path = workdir / f"truncated-{seed}.rdis"
    for n in lengths:
        path.write_text(text[:n], encoding="utf-8")
        check(path)


# -- expressions in place of literals: checked, and round trips when valid ---------------

ATOMS = ["0", "1", "-1", "2.5", "1e3", "0x10", "True", "False", '"a"', '""', "out", "out[0]", "out[1]",
         "velocity", "linear", "bumperStates", "x", "1e308", "255", "256", "-32768", "32768", "0.0", "-0.0",
         'b"\\x01\\x0f"', '"0A"', "out[0][1]", "T", "T.get(1, 2)", "T.keys()"]
OPERATORS = ["+", "-", "*", "/", "//", "%", "**", "<<", ">>", "&", "|", "^", "==", "!=", "<", "<=", ">", ">=",
             "and", "or", "in"]
FUNCTIONS = ["abs", "min", "max", "round", "int", "float", "bool", "str", "clamp", "sqrt", "sin", "cos", "atan2",
             "hypot", "frobnicate", "int_le", "int_be", "f32le", "from_f64be", "nibbles", "from_nibbles", "upper",
             "unhex"]
expressions = st.recursive(
    st.sampled_from(ATOMS),
    lambda e: st.one_of(
        st.tuples(e, st.sampled_from(OPERATORS), e).map(lambda t: f"({t[0]} {t[1]} {t[2]})"),
        st.tuples(st.sampled_from(["-", "not ", "~"]), e).map("".join),
        st.tuples(st.sampled_from(FUNCTIONS), st.lists(e, min_size=1, max_size=3)).map(
            lambda t: f"{t[0]}({', '.join(t[1])})"),
        st.tuples(e, e, e).map(lambda t: f"({t[0]} if {t[1]} else {t[2]})"),
    ),
    max_leaves=6,
)
_LITERAL = re.compile(r'(?<![\w.])\d+(\.\d+)?(?![\w.])|"[^"\n]*"')


@settings(FUZZ, max_examples=fuzz_examples(20))
@given(seed=st.integers(0, len(SEEDS) - 1),
       swaps=st.lists(st.tuples(st.floats(0, 1), expressions), min_size=1, max_size=2))
def test_expression_swaps_round_trip(workdir: Path, seed: int, swaps) -> None:
    """Numbers and strings replaced by arbitrary expressions: diagnostics, never an exception; and
    what checks clean builds, imports back and prints to source that builds to the same JSON."""
    from rdisc.emit.canonical import to_json
    from rdisc.json_import.document import read
    from rdisc.syntax.printer import print_module

    text = SEEDS[seed]
    for at, expr in swaps:
        literals = list(_LITERAL.finditer(text))
        m = literals[int(at * len(literals)) % len(literals)]
        text = text[: m.start()] + expr + text[m.end():]
    path = workdir / "swapped.rdis"
    path.write_text(text, encoding="utf-8")
    c = check(path, tolerate_known=True)
    if c.model is None:
        return
    built = to_json(c.model)
    as_json = workdir / "swapped.json"
    as_json.write_text(built, encoding="utf-8")
    again = check(as_json)
    assert again.model is not None and to_json(again.model) == built
    printed = workdir / "swapped-printed.rdis"
    printed.write_text(print_module(read(str(as_json), built, Diagnostics())), encoding="utf-8")
    third = check(printed)
    assert third.model is not None and to_json(third.model) == built


def test_float_state_initialised_with_a_string(workdir: Path) -> None:
    path = workdir / "float-state.rdis"
    path.write_text('robot r { author "t" }\nstate s: float = "a"\n', encoding="utf-8")
    assert "E401" in {d.code for d in check(path).diagnostics.items}


def test_reply_index_with_a_string_branch(workdir: Path) -> None:
    path = workdir / "reply-index.rdis"
    path.write_text(
        'robot r { author "t" }\nstate s: int = 0\n'
        "connection link: serial { baud 9600 threading single at 10 Hz }\n"
        'primitive p() on link pack "B" (1) unpack ">BB" { s = out["a" if True else 0] }\n'
        "interface poll() periodic triggers o { p() }\n"
        "output o: Range { distance = float(s) }\n",
        encoding="utf-8",
    )
    assert {d.code for d in check(path).diagnostics.items} & {"E305", "E401"}


# -- JSON through the importer ---------------------------------------------------------


def canonical(path: Path) -> str:
    from rdisc.emit.canonical import to_json

    c = compile_path(str(path))
    assert c.model is not None
    return to_json(c.model)


@pytest.fixture(scope="module")
def json_seeds() -> list[str]:
    return [canonical(REPO / "examples" / "create.rdis"), canonical(REPO / "examples" / "koala.rdis"), canonical(BODY)]


JSON_TOKENS = [
    "{", "}", "[", "]", ",", ":", '"', "null", "true", "false", "-0", "1e400", "9" * 400, '"<', '>"',
    '"<__import__(\'os\')>"', '"<1 << 100000>"', '"<2 ** 10 ** 10>"', '"<(((((((((((>"', '"<' + "-" * 150 + '1>"',
    '"\\ud800"', '"\\u0000"', '"{0.__class__}"', '"__out__[7]"', "[" * 150, "{\"a\":" * 120,
    '"name"', '"primitives"', '"interfaces"', '"connections"', '"spp"', '"formatArgs"', '"pack"', '"postActions"',
    '"links"', '"joints"', '"transmissions"', '"toDevice"', '"limit"', '"size"', '"mesh"', '"inertia"',
]


@settings(FUZZ, max_examples=fuzz_examples(60))
@given(which=st.integers(0, 2), edits=st.lists(edit, min_size=1, max_size=5), token=st.sampled_from(JSON_TOKENS),
       at=st.floats(0, 1))
def test_mutated_json(workdir: Path, json_seeds: list[str], which: int, edits, token: str, at: float) -> None:
    text = mutate(json_seeds[which], edits)
    i = int(at * len(text))
    path = workdir / "mutated.json"
    path.write_text(text[:i] + token + text[i:], encoding="utf-8")
    check(path)
    check_import(path)


json_values = st.recursive(
    st.none() | st.booleans() | st.integers() | st.floats(allow_nan=False) | st.text(max_size=10)
    | st.sampled_from(["", "<1>", "<x + >", "<velocity * 1000>", "<__import__('os')>", "<out[0]>", ">Bhh", "B",
                       "{}", "<'a' * 10 ** 9>", "state = __out__[0]"]),
    lambda inner: st.lists(inner, max_size=3) | st.dictionaries(st.text(max_size=8), inner, max_size=3),
    max_leaves=8,
)


def _replace_somewhere(doc, rng: random.Random, value):
    """Replace one randomly chosen member or element (at any depth) by `value`."""
    node = doc
    while True:
        keys = list(node.keys()) if isinstance(node, dict) else list(range(len(node)))
        if not keys:
            return
        key = rng.choice(keys)
        child = node[key]
        if isinstance(child, (dict, list)) and child and rng.random() < 0.7:
            node = child
            continue
        node[key] = value
        return


@settings(FUZZ, max_examples=fuzz_examples(30))
@given(which=st.integers(0, 2), choice=st.integers(0, 2**32 - 1), values=st.lists(json_values, min_size=1, max_size=3),
       drop=st.booleans())
def test_structurally_mutated_json(workdir: Path, json_seeds: list[str], which: int, choice: int, values,
                                   drop: bool) -> None:
    """Valid JSON of the wrong shape: members of the wrong kind, odd expressions, lost members."""
    doc = json.loads(json_seeds[which])
    rng = random.Random(choice)
    for value in values:
        _replace_somewhere(doc, rng, value)
    if drop:
        doc.pop(rng.choice(sorted(doc)), None)
    path = workdir / "structured.json"
    path.write_text(json.dumps(doc, indent=1), encoding="utf-8")
    check(path)
    check_import(path)


def test_thesis_appendix_b_shape_imports(workdir: Path) -> None:
    """The hand-written thesis shape (no types, `""` defaults, `__out__`) is read, not evaluated."""
    doc = {
        "name": "irobotCreate", "author": "Paul Kilgo",
        "stateVariables": [{"type": "int", "name": "bumperStates", "value": ""}],
        "interfaces": [
            {"primitiveCalls": [{"priority": 0, "delay": 100, "arguments": [], "name": "bumpers"}],
             "type": "periodic", "name": "get_bumpers", "triggers": "detect_bump"},
            {"primitiveCalls": [{"priority": 0, "delay": 100, "arguments": ["<round(velocity * 1000)>",
                                                                              "<round(radius * 1000)>"],
                                 "name": "drive"}],
             "type": "adhoc", "name": "drive", "parameters": ["velocity", "radius"]},
        ],
        "domainOutputs": [{"returns": {"distance": "<1.0 if bumperStates == 0 else 0.0>"}, "name": "detect_bump"}],
        "connections": {"spp": [{"baud": 57600, "singleThreading": {"freqHz": 40}, "name": "btserial"}]},
        "primitives": [
            {"name": "drive", "parameters": ["velocity", "radius"], "formatArgs": ["<137>", "", ""],
             "connection": "btserial", "pack": ">Bhh"},
            {"postActions": ["bumperStates= __out__[0]"], "name": "bumpers", "formatArgs": ["<142>", "<7>"],
             "connection": "btserial", "unpack": "B", "pack": "BB"},
        ],
        "domainInterfaces": [{"calls": {"arguments": ["<linear>", "<angular>"], "name": "drive"},
                              "name": "set_velocity", "parameters": ["linear", "angular"]}],
    }
    path = workdir / "thesis.json"
    path.write_text(json.dumps(doc, indent=2), encoding="utf-8")
    c = check(path)
    assert not c.diagnostics.has_errors(), render_plain(c.diagnostics.sorted(), c.sources)
    check_import(path)


# -- giants ------------------------------------------------------------------------------

HEAD = 'robot giant { author "tests" }\nconnection link: serial { baud 9600 }\n'
REFERENCE = REPO / "examples" / "create2.rdis"  # a real description: its check is the unit of cost


def cpu_seconds(work) -> tuple[float, object]:
    """CPU time of this thread doing `work()` (other processes on the machine do not count), and its result."""
    start = time.thread_time()
    result = work()
    return time.thread_time() - start, result


_reference_costs: list[float] = []


def reference_cost() -> float:
    """The CPU time of a check of the real description: the least of three, measured once for the
    giants (each measured it three times again)."""
    if not _reference_costs:
        _reference_costs.append(min(cpu_seconds(lambda: check(REFERENCE))[0] for _ in range(3)))
    return _reference_costs[0]


def giant(workdir: Path, name: str, data: bytes | str, code: str, checks: float = 200) -> Compilation:
    """Check a giant input: it gives `code`, and costs at most `checks` times the check of a real
    description (create2.rdis, about 25 ms of CPU: the default is about 5 s), measured in this process."""
    path = workdir / name
    if isinstance(data, str):
        data = data.encode("utf-8")
    path.write_bytes(data)
    reference = reference_cost()
    cost, c = cpu_seconds(lambda: check(path))
    assert isinstance(c, Compilation)
    assert code in {d.code for d in c.diagnostics.items}, [(d.code, d.message) for d in c.diagnostics.items]
    assert cost < checks * reference, f"{name}: {cost:.2f} s of CPU, {cost / reference:.0f} checks of {REFERENCE.name}"
    return c


def test_nine_mebibyte_file(workdir: Path) -> None:
    line = "# " + "x" * 1021 + "\n"
    giant(workdir, "big.rdis", HEAD + line * (9 * 1024), "E005")


def test_nine_mebibytes_of_json(workdir: Path) -> None:
    giant(workdir, "big.json", '{"name": "' + "x" * (9 * 1024 * 1024) + '"}', "E005")


def test_hundred_thousand_nested_parentheses(workdir: Path) -> None:
    expr = "(" * 100_000 + "1" + ")" * 100_000
    giant(workdir, "parens.rdis", HEAD + f'primitive p() on link pack "B" ({expr})\n', "E005")


def test_fifty_thousand_unary_minus_signs(workdir: Path) -> None:
    giant(workdir, "minus.rdis", HEAD + f'primitive p() on link pack "b" ({"-" * 50_000}1)\n', "E005")


def test_fifty_thousand_nots_and_tildes(workdir: Path) -> None:
    giant(workdir, "not.rdis", HEAD + f'state s: bool = {"not " * 50_000}True\n', "E005")
    giant(workdir, "tilde.rdis", HEAD + f'state s: int = {"~" * 50_000}1\n', "E005")


def test_deeply_nested_binary_operators(workdir: Path) -> None:
    expr = "1" + " + (1" * 20_000 + ")" * 20_000
    giant(workdir, "sum.rdis", HEAD + f'state s: int = {expr}\n', "E005")


def test_five_megabyte_single_line_string(workdir: Path) -> None:
    """A line (so a string literal) is at most 65536 characters: longer ones are refused before
    the parser, whose lexer took seconds and gigabytes over them."""
    text = HEAD + 'state spare: int = 0\nprimitive p() on link format "' + "A" * (5 * 1000 * 1000) + '" ()\n'
    c = giant(workdir, "string.rdis", text, "E005", checks=320)
    assert [d.message for d in c.diagnostics.items if d.code == "E005"] == [
        "line of 5000034 characters; the limit is 65536"]


def test_two_megabyte_unterminated_string_is_a_diagnostic(workdir: Path) -> None:
    text = HEAD + 'primitive p() on link format "' + "A" * (2 * 1000 * 1000) + "\n"
    c = giant(workdir, "open-string.rdis", text, "E005", checks=600)
    assert [d.message for d in c.diagnostics.items if d.code == "E005"] == [
        "line of 2000030 characters; the limit is 65536"]


def test_deeply_nested_json(workdir: Path) -> None:
    giant(workdir, "nested.json", "[" * 100_000 + "]" * 100_000, "E005")
    giant(workdir, "nested-objects.json", '{"a":' * 50_000 + "1" + "}" * 50_000, "E005")


def test_binary_junk(workdir: Path) -> None:
    data = random.Random(1).randbytes(1 << 20)
    c = giant(workdir, "junk.rdis", data, "E006")
    assert [d.code for d in c.diagnostics.items] == ["E006"]
    giant(workdir, "junk.json", data, "E006")


def test_fifty_thousand_syntax_errors_are_capped(workdir: Path) -> None:
    c = giant(workdir, "errors.rdis", HEAD + "state $\n" * 50_000, "E002")
    assert len(c.diagnostics.items) <= 200


def _body(links: int, conversion: str = "round(position * 195.3) + 512") -> str:
    """A chain of `links` links, each turned by a revolute joint through a servo's goal."""
    lines = ['primitive servo(goal: int in 0..1023) on link pack ">H" (goal)', "link l0 { visual box(1, 1, 1) }"]
    for i in range(1, links):
        lines += [f"link l{i} {{ visual box(1, 1, 1) mass 1 inertia [1, 1, 1] }}",
                  f"joint j{i}: revolute l{i - 1} -> l{i} {{ limit -1.5..1.5 velocity 2 effort 1 axis [0, 0, 1] }}",
                  (f"transmission t{i}: j{i} {{ command position to servo.goal "
                  f"{{ raw = {conversion}  position = (raw - 512) / 195.3 }} }}")]
    return HEAD + "\n".join(lines) + "\n"


def test_two_thousand_links_check_in_linear_time(workdir: Path) -> None:
    """A body of 2,000 links, joints and transmissions (each conversion sampled 33 times) costs
    what a description of its size costs: the tree is walked once, no joint searched for."""
    path = workdir / "chain.rdis"
    path.write_text(_body(2000), encoding="utf-8")
    reference = reference_cost()
    cost, c = cpu_seconds(lambda: check(path))
    assert isinstance(c, Compilation) and c.model is not None, c.diagnostics.items
    assert len(c.model.joints) == 1999 and len(c.model.transmissions) == 1999
    assert cost < 200 * reference, f"{cost:.2f} s of CPU, {cost / reference:.0f} checks of {REFERENCE.name}"


def test_huge_conversions_are_sampled_within_a_budget(workdir: Path) -> None:
    """Conversions of thousands of operations each: sampling stops at 50,000 operations in all."""
    group = "(" + " + ".join(["position * 0.01"] * 20) + ")"
    wide = "round(" + " + ".join([f"({' + '.join([group] * 20)})"] * 5) + ")"  # 2,000 products
    c = giant(workdir, "conversions.rdis", _body(12, wide), "E005")
    assert [d.message for d in c.diagnostics.items if d.code == "E005"] == [
        "the body's conversions have more than 50000 operations in all: too many to check against the device"]
