"""A catalogue of hostile descriptions: each is refused with a specific diagnostic, and
none of it is ever evaluated.

A description may come from a device or a network (DESIGN.md), and the thesis's
interpreter ran `eval`/`exec` on its strings. Every entry below is tried as .rdis
source, as a thesis-style JSON description (`"<expr>"` strings), and through the
`rdisc import` verb (in-process for all, and in a real subprocess for one entry
per diagnostic code). While the
in-process checks run, an audit hook (PEP 578) records what the interpreter
does: no code may be compiled or executed, no process started, no file opened
but the description and the standard adapters. Payloads that would leave a
file behind if they ran point at a sentinel path that must stay absent.
"""

from __future__ import annotations

import io
import json
import os
import re
import sys
import threading
import time
import tokenize
from concurrent.futures import ThreadPoolExecutor
from dataclasses import dataclass
from pathlib import Path

import pytest

import rdisc
from rdisc.compile import compile_path
from rdisc.resources import stdlib_path

REPO = Path(__file__).resolve().parents[2]
SENTINEL = "/tmp/rdisc-hostile-sentinel"  # a payload that ran would create it


@dataclass(frozen=True)
class Case:
    id: str
    kind: str  # "expr": a format argument; "format": a `format` template; "regex"; "state": an initial value
    payload: str
    code: str  # the one diagnostic code expected, from source and from JSON alike
    json_code: str | None = None  # when the JSON route reports differently


CASES = [
    # -- reaching Python: names, attributes, dunders ----------------------------------------
    Case("dunder-import", "expr", f"__import__('os').system('touch {SENTINEL}')", "E002"),
    Case("dunder-import-dq", "expr", '__import__("os")', "E002"),
    Case("builtins", "expr", "__builtins__", "E002"),
    Case("leading-underscore", "expr", "_x + 1", "E002"),
    Case("attribute", "expr", "x.real", "E102"),  # read as an enum member: no enum `x`
    Case("attribute-chain", "expr", "x.__class__.__mro__", "E002"),
    Case("conditional-escape", "expr", "x if True else __import__('os')", "E002"),
    # -- functions that are not built-ins of RDIS --------------------------------------------
    Case("eval", "expr", 'eval("1")', "E106"),
    Case("exec", "expr", f'exec("import os; os.system(touch {SENTINEL})")', "E106"),
    Case("open", "expr", f'open("{SENTINEL}", "w")', "E106"),
    Case("getattr", "expr", 'getattr(x, "real")', "E106"),
    Case("compile", "expr", 'compile("1", "x", "eval")', "E106"),
    Case("globals", "expr", "globals()", "E106"),
    Case("type", "expr", "type(x)", "E106"),
    Case("breakpoint", "expr", "breakpoint()", "E106"),
    # -- Python syntax that RDIS does not have -----------------------------------------------
    Case("lambda", "expr", "lambda: 1", "E001"),
    Case("lambda-call", "expr", "(lambda y: y)(1)", "E001"),
    Case("list-comprehension", "expr", '[c for c in "ab"]', "E001"),
    Case("generator", "expr", 'sum(c for c in "ab")', "E001"),
    Case("walrus", "expr", "(y := 1)", "E001"),
    Case("starred", "expr", "*x", "E001"),
    Case("f-string", "expr", 'f"{x}"', "E001"),
    Case("statement", "expr", "x; import os", "E001"),  # `;` is a character of RDIS now (a matrix's rows)
    Case("single-quotes", "expr", "'a'", "E002"),
    # -- work that would never end (or never fit in memory) ------------------------------
    Case("power-tower", "expr", "2 ** 10 ** 10", "E405"),
    Case("huge-shift", "expr", "1 << 100000", "E405"),
    Case("string-times-billion", "expr", '"a" * 10 ** 9', "E404"),
    Case("huge-literal", "expr", "9" * 100, "E004"),
    # -- format strings that reach into objects or allocate ----------------------------
    Case("format-attribute", "format", "D{0.__class__}", "E303"),
    Case("format-globals", "format", "{0.__init__.__globals__}", "E303"),
    Case("format-index", "format", "{0[0]}", "E303"),
    Case("format-conversion", "format", "{!r}", "E303"),
    Case("format-named", "format", "{x}", "E303"),
    Case("format-nested", "format", "{:{}}", "E303"),
    Case("format-giant-width", "format", "{:>999999999}", "E303"),
    Case("format-giant-precision", "format", "{:.99999999999f}", "E303"),
    # -- struct formats and regexes that would allocate or hang the checker ------------
    Case("pack-giant-count", "pack", "999999999x", "E301"),
    Case("pack-pointer", "pack", "P", "E301"),
    Case("regex-giant-repeat", "regex", "a{4294967295}", "E304"),
    Case("regex-deep-groups", "regex", "(" * 2000 + "a" + ")" * 2000, "E304"),
    # -- names --------------------------------------------------------------------------------
    Case("underscore-state", "state-name", "_secret", "E002", json_code="E008"),
    Case("dunder-state", "state-name", "__class__", "E002", json_code="E008"),
]


# -- building the descriptions ------------------------------------------------------------


def rdis_source(case: Case) -> str:
    head = 'robot hostile { author "tests" }\nconnection link: serial { baud 9600 }\n'
    tail = "interface go() { p(1) }\ninput i: Contact -> go()\n"
    if case.kind == "expr":
        return head + f'primitive p(x: int) on link pack ">q" ({case.payload})\n' + tail
    if case.kind == "format":
        return head + f'primitive p(x: int) on link format "{case.payload}" (x)\n' + tail
    if case.kind == "pack":
        return head + f'primitive p(x: int) on link pack "{case.payload}" ()\n' + tail
    if case.kind == "regex":
        return head + f'primitive p(x: int) on link pack ">q" (x) regex r"{case.payload}"\n' + tail
    if case.kind == "state-name":
        return head + f"state {case.payload}: int = 0\n" + 'primitive p(x: int) on link pack ">q" (x)\n' + tail
    raise AssertionError(case.kind)


def thesis_json(case: Case) -> str:
    primitive: dict = {"name": "p", "parameters": ["x"], "connection": "link", "pack": ">q", "formatArgs": ["<x>"]}
    doc: dict = {
        "name": "hostile",
        "author": "tests",
        "stateVariables": [],
        "connections": {"spp": [{"name": "link", "baud": 9600}]},
        "primitives": [primitive],
        "interfaces": [{"name": "go", "type": "adhoc", "primitiveCalls": [{"name": "p", "arguments": ["<1>"]}]}],
        "domainInterfaces": [{"name": "i", "calls": {"name": "go", "arguments": []}}],
    }
    if case.kind == "expr":
        primitive["formatArgs"] = [f"<{case.payload}>"]
    elif case.kind == "format":
        del primitive["pack"]
        primitive["format"] = case.payload
    elif case.kind == "pack":
        primitive["pack"] = case.payload
        primitive["formatArgs"] = []
    elif case.kind == "regex":
        primitive["regex"] = case.payload
    elif case.kind == "state-name":
        doc["stateVariables"] = [{"name": case.payload, "type": "int", "value": "<0>"}]
    return json.dumps(doc, indent=2)


#: each kind's harmless payload: its description is clean
HARMLESS = {"expr": "x", "format": "{}", "pack": ">q", "regex": "(\\d+)", "state-name": "secret"}


def harmless_sources(kind: str) -> dict[str, str]:
    """The templates of `kind` with its harmless payload, as .rdis source and as thesis JSON."""
    case = Case("clean", kind, HARMLESS[kind], "")
    texts = {".rdis": rdis_source(case), ".json": thesis_json(case)}
    if kind == "pack":  # the template passes no arguments: give the harmless format none to take
        texts = {suffix: text.replace('pack ">q" ()', 'pack "x" ()').replace('"pack": ">q"', '"pack": "x"')
                 for suffix, text in texts.items()}
    return texts


def codes_of(compilation) -> set[str]:
    return {d.code for d in compilation.diagnostics.items}


# -- watching the interpreter -------------------------------------------------------------

_FORBIDDEN = ("exec", "compile", "os.system", "os.exec", "os.spawn", "os.posix_spawn", "os.fork", "os.forkpty",
              "subprocess.Popen", "pty.spawn", "socket.", "ctypes.", "builtins.input", "webbrowser.open",
              "os.remove", "os.rename", "os.mkdir", "shutil.")
_watch = threading.local()


def _hook(event: str, args: tuple) -> None:
    log = getattr(_watch, "log", None)
    if log is not None and (event.startswith(_FORBIDDEN) or event == "open"):
        log.append((event, args[0] if args else None))


sys.addaudithook(_hook)  # hooks cannot be removed; outside `watched` it only reads a thread-local


def watched(path: Path):
    """Compile `path` and return (compilation, forbidden events, files opened)."""
    _watch.log = []
    try:
        c = compile_path(str(path))
    finally:
        log, _watch.log = _watch.log, None
    opened = {str(Path(str(a)).resolve()) for e, a in log if e == "open" and isinstance(a, (str, os.PathLike))}
    forbidden = [(e, a) for e, a in log if e != "open"]
    return c, forbidden, opened


@pytest.fixture(scope="module")
def warm(tmp_path_factory) -> Path:
    """Import everything the pipeline imports lazily, so the watch sees only the check itself;
    beside each entry's files, each kind's harmless twins (`clean-KIND.rdis`, `.json`)."""
    folder = tmp_path_factory.mktemp("hostile")
    for case in CASES:
        for name, text in ((f"{case.id}.rdis", rdis_source(case)), (f"{case.id}.json", thesis_json(case))):
            (folder / name).write_text(text, encoding="utf-8")
            compile_path(str(folder / name))
    for kind in HARMLESS:
        for suffix, text in harmless_sources(kind).items():
            (folder / f"clean-{kind}{suffix}").write_text(text, encoding="utf-8")
    compile_path(str(REPO / "examples" / "create.rdis"))
    return folder


#: how many times its harmless twin's check the check of a hostile entry may cost (all cost
#: about the same today; a payload that ran, `2 ** 10 ** 10` or `"a" * 10 ** 9`, costs millions)
COST_FACTOR = 50


def cpu_seconds(path: Path) -> float:
    """CPU time of this thread checking `path`: other processes on a busy machine do not count."""
    start = time.thread_time()
    compile_path(str(path))
    return time.thread_time() - start


_twin_costs: dict[Path, float] = {}


def twin_cost(twin: Path) -> float:
    """The least of three checks of a harmless twin, measured once for the ten twins (each served
    eight entries or so, three checks each time)."""
    if twin not in _twin_costs:
        _twin_costs[twin] = min(cpu_seconds(twin) for _ in range(3))
    return _twin_costs[twin]


def assert_not_evaluated(path: Path, kind: str) -> set[str]:
    start = time.thread_time()
    c, forbidden, opened = watched(path)
    cost = time.thread_time() - start
    assert forbidden == [], f"the check of {path.name} did {forbidden}"
    allowed = {str(path.resolve()), str(stdlib_path().resolve())}
    assert opened <= allowed, f"the check of {path.name} opened {opened - allowed}"
    assert not os.path.exists(SENTINEL)
    # the least of three checks of each, so that a pause of the interpreter's (a garbage
    # collection of the whole test process) in one of them does not count
    cost = min(cost, cpu_seconds(path), cpu_seconds(path))
    twin = path.with_name(f"clean-{kind}{path.suffix}")
    reference = twin_cost(twin)
    assert cost < COST_FACTOR * reference, (
        f"{path.name} cost {cost * 1000:.0f} ms of CPU, {cost / reference:.0f} times {twin.name}: something was computed")
    return codes_of(c)


# -- the catalogue --------------------------------------------------------------------------


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_source_is_refused_and_not_evaluated(case: Case, warm: Path) -> None:
    assert assert_not_evaluated(warm / f"{case.id}.rdis", case.kind) == {case.code}


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_json_is_refused_and_not_evaluated(case: Case, warm: Path) -> None:
    assert assert_not_evaluated(warm / f"{case.id}.json", case.kind) == {case.json_code or case.code}


def test_the_templates_are_clean_without_the_payload(tmp_path: Path) -> None:
    """The catalogue's descriptions are correct apart from their payload, so each code is the payload's."""
    assert set(HARMLESS) == {case.kind for case in CASES}
    for kind in HARMLESS:
        for suffix, text in harmless_sources(kind).items():
            name = f"clean{suffix}"
            (tmp_path / name).write_text(text, encoding="utf-8")
            c = compile_path(str(tmp_path / name))
            assert codes_of(c) <= {"W103"}, (kind, name, [(d.code, d.message) for d in c.diagnostics.items])


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_rdisc_import_verb_refuses(case: Case, warm: Path, capsys: pytest.CaptureFixture[str]) -> None:
    """The `import` verb itself (in-process: one subprocess per entry would cost seconds)."""
    from rdisc.cli.main import main

    out = warm / f"{case.id}.imported.rdis"
    assert main(["import", str(warm / f"{case.id}.json"), "-o", str(out)]) == 1
    err = capsys.readouterr().err
    assert f"error[{case.json_code or case.code}]" in err
    assert_not_laundered(case, out)
    assert not os.path.exists(SENTINEL)


def assert_not_laundered(case: Case, out: Path) -> None:
    """`rdisc import` writes what it could read even when it does not check (the exit status
    says so). What it writes must not turn the payload into a clean description: either the
    source is refused again, or the payload is gone (left out with its element)."""
    if out.exists():
        text = out.read_text(encoding="utf-8")
        assert compile_path(str(out)).diagnostics.has_errors() or case.payload not in text, text


# One entry per code, through a real `rdisc import` subprocess.
ONE_PER_CODE = list({c.json_code or c.code: c for c in CASES}.values())


@pytest.fixture(scope="module")
def imports(rdisc_process, warm: Path) -> dict[str, object]:
    def one(case: Case):
        out = warm / f"{case.id}.subprocess.rdis"
        return rdisc_process("import", warm / f"{case.id}.json", "-o", out), out

    with ThreadPoolExecutor(max_workers=max(2, os.cpu_count() or 2)) as pool:
        return dict(zip((c.id for c in ONE_PER_CODE), pool.map(one, ONE_PER_CODE)))


@pytest.mark.parametrize("case", ONE_PER_CODE, ids=[c.id for c in ONE_PER_CODE])
def test_rdisc_import_subprocess_refuses(case: Case, imports) -> None:
    result, out = imports[case.id]
    assert result.returncode == 1, result.stderr
    assert "Traceback" not in result.stderr and "internal error" not in result.stderr
    assert f"error[{case.json_code or case.code}]" in result.stderr
    assert_not_laundered(case, out)
    assert not os.path.exists(SENTINEL)


def test_the_sentinel_is_not_there_to_begin_with() -> None:
    assert not os.path.exists(SENTINEL), f"remove {SENTINEL}: it would hide a payload that ran"


# -- the package itself -----------------------------------------------------------------


def _calls(source: str) -> list[tuple[int, str]]:
    """`eval(`, `exec(`, `compile(` written as calls in Python source (not in strings or comments);
    `re.compile(` is a regular expression, not code, and is allowed."""
    tokens = [t for t in tokenize.generate_tokens(io.StringIO(source).readline)
              if t.type not in (tokenize.COMMENT, tokenize.NL, tokenize.NEWLINE, tokenize.INDENT, tokenize.DEDENT)]
    found = []
    for i, tok in enumerate(tokens[:-1]):
        if tok.type == tokenize.NAME and tok.string in ("eval", "exec", "compile") and tokens[i + 1].string == "(":
            after_re_dot = i >= 2 and tokens[i - 1].string == "." and tokens[i - 2].string == "re"
            if not after_re_dot:
                found.append((tok.start[0], tok.string))
    return found


#: where `_calls` can find a call: the name, then only blanks, line breaks, comments and `\` before `(`
_MAYBE_A_CALL = re.compile(r"(?<!\w)(?:eval|exec|compile)(?:\s|\\|#[^\n]*)*\(")


def _calls_in(source: str) -> list[tuple[int, str]]:
    """`_calls(source)`, tokenized only when the text has the name and a `(` after it as above (one
    file in ten: tokenizing the package's 2.5 MB took 2.4 s of CPU)."""
    return _calls(source) if _MAYBE_A_CALL.search(source) else []


def test_the_finder_finds_what_it_should() -> None:
    assert _calls("x = eval(s)\nexec (code)\nbuiltins.compile(t, 'f', 'exec')\n") == [
        (1, "eval"), (2, "exec"), (3, "compile")]
    assert _calls("p = re.compile(r'x')\n# eval(x)\ns = 'exec(x)'\ndef evaluate(e): ...\n") == []
    for source in ("x = eval(s)\n", "exec (code)\n", "f(eval\n(s))\n", "f(exec  # why\n (s))\n", "x = compile \\\n(t)\n"):
        assert _calls_in(source) == _calls(source) != [], source  # the pre-filter passes each call on


def test_the_package_has_no_eval_exec_or_compile() -> None:
    package = Path(rdisc.__file__).resolve().parent
    files = sorted(package.rglob("*.py"))
    assert len(files) > 10
    offenders = [f"{f.relative_to(package)}:{line}: {name}(" for f in files
                 for line, name in _calls_in(f.read_text(encoding="utf-8"))]
    assert offenders == []
    # the same, by grep, on text: only `re.compile(` may match
    pattern = re.compile(r"(?<![\w.])(eval|exec|compile)\s*\(|(?<!\bre)\.(eval|exec|compile)\s*\(")
    grepped = [f"{f.relative_to(package)}:{n}: {line.strip()}" for f in files
               for n, line in enumerate(f.read_text(encoding="utf-8").splitlines(), 1)
               if pattern.search(line.split("#")[0]) and not line.strip().startswith(('"', "'"))]
    assert grepped == []
