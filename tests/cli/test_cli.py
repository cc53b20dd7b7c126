"""The `rdisc` command as a user meets it: real files, exit codes. The tests that take
`rdisc_process` run `python -m rdisc` in a subprocess (the entry point, its exit status, no
traceback); the others call the same entry function in this process (tests/conftest.py).

Exit codes: 0 clean (warnings allowed), 1 errors in a description, 2 a usage
problem (unknown verb or option, a file that cannot be read, an unknown code),
3 an internal error (a bug; never expected here).
"""

from __future__ import annotations

import json
import random
from pathlib import Path

import pytest

from rdisc import __version__
from rdisc.diagnostics.codes import CODES

REPO = Path(__file__).resolve().parents[2]
CREATE = "examples/create.rdis"
KOALA = "examples/koala.rdis"
GOLDEN = REPO / "tests" / "golden" / "diagnostics"


def no_crash(result) -> None:
    assert "Traceback" not in result.stderr, result.stderr
    assert "internal error" not in result.stderr, result.stderr
    assert result.returncode in (0, 1, 2), (result.returncode, result.stderr)


def write(tmp_path: Path, name: str, text: str) -> Path:
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return path


CLEAN = """\
robot clean { author "tests" }
connection link: serial { baud 9600 }
primitive ping() on link pack "B" (1)
interface go() { ping() }
input start: Contact -> go()
"""


# -- exit codes ------------------------------------------------------------------


@pytest.mark.parametrize("example", [CREATE, KOALA])
def test_clean_description_exits_0_silently(rdisc_process, example: str) -> None:
    result = rdisc_process("check", example)
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")


def test_only_warnings_exit_0(rdisc, tmp_path: Path) -> None:
    path = write(tmp_path, "warn.rdis", CLEAN + 'state spare: int = 0\n')
    result = rdisc("check", path)
    assert result.returncode == 0
    assert "warning[W103]: state variable `spare` is never used" in result.stderr
    assert result.stderr.rstrip().endswith("1 warning emitted")


def test_errors_exit_1(rdisc_process, tmp_path: Path) -> None:
    path = write(tmp_path, "bad.rdis", CLEAN.replace("baud 9600", "baud 0"))
    result = rdisc_process("check", path)
    assert result.returncode == 1
    assert "error[E204]: the baud rate must be a positive integer, not 0" in result.stderr
    assert result.stderr.rstrip().endswith("1 error emitted")


def test_missing_file_exits_2(rdisc_process, tmp_path: Path) -> None:
    result = rdisc_process("check", tmp_path / "nowhere.rdis")
    assert result.returncode == 2
    assert "error[E006]: cannot read" in result.stderr
    assert "nowhere.rdis" in result.stderr


def test_a_directory_is_not_one_description_exits_2(rdisc, tmp_path: Path) -> None:
    """`rdisc check` takes a directory for the descriptions in it; the verbs of one description don't."""
    folder = tmp_path / "folder.rdis"
    folder.mkdir()
    result = rdisc("dump", folder)
    assert result.returncode == 2
    assert "error[E006]: cannot read" in result.stderr


def test_a_missing_file_among_good_ones_exits_2(rdisc, tmp_path: Path) -> None:
    result = rdisc("check", CREATE, tmp_path / "nowhere.rdis", KOALA)
    assert result.returncode == 2
    assert result.stderr.count("error[") == 1


@pytest.mark.parametrize(
    "argv, words",
    [
        (["frobnicate"], "invalid choice"),
        ([], "required"),
        (["check"], "required"),
        (["check", "--format", "xml", CREATE], "invalid choice"),
        (["check", "--no-such-option", CREATE], "unrecognized arguments"),
        (["build"], "required"),
        (["import"], "required"),
    ],
    ids=["unknown-verb", "no-verb", "check-no-file", "bad-format", "bad-option", "build-no-file", "import-no-file"],
)
def test_usage_errors_exit_2(rdisc, argv: list[str], words: str) -> None:
    result = rdisc(*argv)
    assert result.returncode == 2
    assert "usage: rdisc" in result.stderr
    assert words in result.stderr
    assert result.stdout == ""


def test_version(rdisc_process) -> None:
    result = rdisc_process("--version")
    assert (result.returncode, result.stdout, result.stderr) == (0, f"rdisc {__version__}\n", "")


# -- explain -----------------------------------------------------------------------


@pytest.mark.parametrize("spelling", ["E102", "e102", "unknown-element"])
def test_explain_a_code(rdisc, spelling: str) -> None:
    result = rdisc("explain", spelling)
    assert result.returncode == 0
    assert result.stdout == f"E102 (unknown-element)\n\n{CODES['E102'].explanation}\n"
    assert result.stdout.startswith(
        "E102 (unknown-element)\n\nA reference to an element that is not declared: a primitive or interface called\n"
    )


def test_explain_unknown_code_exits_2(rdisc) -> None:
    result = rdisc("explain", "nope")
    assert result.returncode == 2
    assert result.stdout == ""
    assert "no diagnostic code `nope`" in result.stderr


def test_explain_lists_every_code(rdisc) -> None:
    result = rdisc("explain")
    assert result.returncode == 0
    assert result.stdout.splitlines() == [f"{c.id}  {c.name}" for c in CODES.values()]
    assert len(result.stdout.splitlines()) == len(CODES) >= 40


# -- verbose budget, JSON diagnostics ----------------------------------------------


def test_verbose_prints_the_budget_of_create_polled(rdisc) -> None:
    polled = "tests/runtime/data/polled/create.rdis"  # examples/create.rdis before its bumpers became a sensor
    result = rdisc("check", "-v", polled)
    assert result.returncode == 0
    assert result.stderr == ""
    assert result.stdout.splitlines() == [
        f"{polled}: connection `btserial`: 57600 baud, 5760 bytes/s",
        "  every tick (40 Hz, 25.0 ms):",
        "    get_bumpers: 3 bytes, 0.52 ms on the wire + 15 ms of delays = 15.52 ms",
        "    15.52 ms of 25.0 ms per tick",
        "  keepalive every 1000 ms:",
        "    get_bumpers: 3 bytes, 0.52 ms on the wire + 15 ms of delays = 15.52 ms",
        "  scheduled: 123.0 bytes/s, 2.1% of the link",
    ]


def test_verbose_prints_the_budget_of_create_with_its_sensor(rdisc) -> None:
    """The bumpers, a sensor kept for 100 ms, are counted at the rate they are read (10 Hz), not
    at the 40 Hz of the output that reads them; the tick that reads them carries their exchange."""
    result = rdisc("check", "-v", CREATE)
    assert result.returncode == 0
    assert result.stderr == ""
    assert result.stdout.splitlines() == [
        "examples/create.rdis: connection `btserial`: 57600 baud, 5760 bytes/s",
        "  every tick (40 Hz, 25.0 ms):",
        "    get_bumpers: 0 bytes, 0.00 ms on the wire + 0 ms of delays = 0.00 ms",
        "    0.52 ms of 25.0 ms per tick",
        "  keepalive every 1000 ms:",
        "    get_bumpers: 0 bytes, 0.00 ms on the wire + 0 ms of delays = 0.00 ms",
        "  sensor bumperStates: 3 bytes, 0.52 ms on the wire, read at 10 Hz",
        "  scheduled: 30.0 bytes/s, 0.5% of the link",
    ]


def test_verbose_names_the_file_of_each_budget(rdisc) -> None:
    result = rdisc("check", "-v", KOALA, CREATE)
    assert (result.returncode, result.stderr) == (0, "")
    assert [line for line in result.stdout.splitlines() if not line.startswith(" ")] == [
        "examples/koala.rdis: connection `rs232`: 38400 baud, 3840 bytes/s",
        "examples/create.rdis: connection `btserial`: 57600 baud, 5760 bytes/s",
    ]


def test_a_directory_is_each_description_in_it_in_sorted_order(rdisc, tmp_path: Path) -> None:
    result = rdisc("check", "-v", "examples/")
    assert (result.returncode, result.stderr) == (0, "")
    described = sorted(f"examples/{p.name}" for p in (REPO / "examples").glob("*.rdis"))
    assert list(dict.fromkeys(line.partition(": ")[0] for line in result.stdout.splitlines()
                              if not line.startswith(" "))) == described
    (tmp_path / "b.rdis").write_text((REPO / CREATE).read_text(encoding="utf-8"), encoding="utf-8")
    (tmp_path / "a.json").write_text("{", encoding="utf-8")
    (tmp_path / "notes.txt").write_text("not a description", encoding="utf-8")
    result = rdisc("check", "-v", tmp_path)
    assert result.returncode == 1
    assert f"--> {tmp_path}/a.json" in result.stderr and "notes.txt" not in result.stderr
    assert result.stdout.splitlines()[0] == f"{tmp_path}/b.rdis: connection `btserial`: 57600 baud, 5760 bytes/s"
    empty = tmp_path / "empty"
    empty.mkdir()
    result = rdisc("check", empty)
    assert (result.returncode, result.stderr) == (2, f"rdisc check: no .rdis or .json description in {empty}\n")


def test_long_verbose_flag_is_the_same(rdisc) -> None:
    assert rdisc("check", "--verbose", CREATE).stdout == rdisc("check", "-v", CREATE).stdout


def test_json_of_several_files_is_one_array(rdisc) -> None:
    files = [CREATE, "tests/golden/diagnostics/E101.rdis", "tests/golden/diagnostics/W103.rdis", KOALA]
    result = rdisc("check", "--format", "json", *files)
    assert result.returncode == 1
    assert result.stderr == ""
    items = json.loads(result.stdout)
    assert isinstance(items, list)
    assert [(i["file"], i["code"]) for i in items] == [
        ("tests/golden/diagnostics/E101.rdis", "E101"),
        ("tests/golden/diagnostics/W103.rdis", "W103"),
    ]


def test_json_of_a_clean_file_is_an_empty_array(rdisc) -> None:
    result = rdisc("check", "--format", "json", CREATE)
    assert (result.returncode, json.loads(result.stdout), result.stderr) == (0, [], "")


def test_json_columns_are_utf16(rdisc, tmp_path: Path) -> None:
    """An astral character before the fault counts two UTF-16 units in JSON, as LSP wants;
    the text counts code points, and the caret sits under the fault (the emoji is two cells wide)."""
    path = write(tmp_path, "wide.rdis", CLEAN + 'state s: string = "\U0001F916" $\n')
    items = json.loads(rdisc("check", "--format", "json", path).stdout)
    (item,) = [i for i in items if i["code"] == "E002"]
    assert item["range"]["start"] == {"line": 5, "character": len('state s: string = "') + 2 + len('" ')}
    text = rdisc("check", path).stderr
    assert f"wide.rdis:6:{len('state s: string = ') + 5}" in text
    caret = "  | " + " " * (len('state s: string = "') + 2 + len('" ')) + "^ no token"
    assert '6 | state s: string = "\U0001F916" $\n' + caret in text


# -- build and import ------------------------------------------------------------


@pytest.mark.parametrize("example", [CREATE, KOALA])
def test_build_then_import_round_trips(rdisc, tmp_path: Path, example: str) -> None:
    first = tmp_path / "first.json"
    result = rdisc("build", example, "-o", first)
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")
    model = json.loads(first.read_text(encoding="utf-8"))
    assert isinstance(model, dict) and model["name"]

    source = tmp_path / "imported.rdis"
    result = rdisc("import", first, "-o", source)
    assert (result.returncode, result.stdout, result.stderr) == (0, "", "")
    assert source.read_text(encoding="utf-8").startswith(f"robot {model['name']}")

    assert rdisc("check", source).returncode == 0
    second = tmp_path / "second.json"
    result = rdisc("build", source, "-o", second)
    assert result.returncode == 0, result.stderr
    assert second.read_bytes() == first.read_bytes()


def test_build_without_output_writes_stdout(rdisc, tmp_path: Path) -> None:
    out = tmp_path / "create.json"
    assert rdisc("build", CREATE, "-o", out).returncode == 0
    result = rdisc("build", CREATE)
    assert result.returncode == 0
    assert result.stdout.encode("utf-8") == out.read_bytes()


def test_build_of_canonical_json_reproduces_it(rdisc, tmp_path: Path) -> None:
    first = tmp_path / "create.json"
    assert rdisc("build", CREATE, "-o", first).returncode == 0
    result = rdisc("build", first)
    assert result.returncode == 0, result.stderr
    assert result.stdout.encode("utf-8") == first.read_bytes()


def test_build_with_errors_writes_nothing(rdisc, tmp_path: Path) -> None:
    out = tmp_path / "out.json"
    result = rdisc("build", "tests/golden/diagnostics/E102.rdis", "-o", out)
    assert result.returncode == 1
    assert "error[E102]" in result.stderr
    assert not out.exists()


def test_build_into_a_missing_folder_exits_2(rdisc, tmp_path: Path) -> None:
    result = rdisc("build", CREATE, "-o", tmp_path / "no" / "such" / "folder" / "out.json")
    no_crash(result)
    assert result.returncode == 2
    assert "cannot write" in result.stderr


def test_import_of_json_with_errors_writes_what_it_read_and_exits_1(rdisc, tmp_path: Path) -> None:
    """Fixing a legacy description is easier in .rdis: the source is written, the status says it fails."""
    out = tmp_path / "out.rdis"
    result = rdisc("import", "tests/golden/diagnostics/E008.json", "-o", out)
    assert result.returncode == 1
    assert "error[E008]" in result.stderr
    assert out.read_text(encoding="utf-8").startswith("robot golden {")
    assert "primitive" not in out.read_text(encoding="utf-8")  # the malformed member is left out


def test_import_of_broken_json_syntax_writes_nothing(rdisc, tmp_path: Path) -> None:
    path = write(tmp_path, "broken.json", '{"name": "x", "author": ')
    out = tmp_path / "out.rdis"
    result = rdisc("import", path, "-o", out)
    no_crash(result)
    assert result.returncode == 1
    assert "error[E008]" in result.stderr
    assert not out.exists()


# -- junk input --------------------------------------------------------------------


def test_binary_junk_is_a_diagnostic(rdisc_process, tmp_path: Path) -> None:
    path = tmp_path / "junk.rdis"
    path.write_bytes(random.Random(7).randbytes(4096))
    result = rdisc_process("check", path)
    no_crash(result)
    assert result.returncode == 2
    assert "error[E006]" in result.stderr and "not UTF-8 text" in result.stderr


def test_binary_junk_as_json_is_a_diagnostic(rdisc, tmp_path: Path) -> None:
    path = tmp_path / "junk.json"
    path.write_bytes(b"\x89PNG\r\n\x1a\n" + random.Random(8).randbytes(2048))
    for verb in ("check", "build", "import"):
        result = rdisc(verb, path)
        no_crash(result)
        assert result.returncode == 2
        assert "error[E006]" in result.stderr


def test_utf8_junk_with_control_characters_is_a_diagnostic(rdisc, tmp_path: Path) -> None:
    rng = random.Random(9)
    text = "".join(chr(rng.choice([0, 1, 7, 8, 27, 127, 0x85, 0x2028, 0xFEFF, 0x1F916, rng.randrange(32, 0x3000)]))
                   for _ in range(3000))
    path = tmp_path / "junk.rdis"
    path.write_text(text, encoding="utf-8")
    for fmt in ("text", "json"):
        result = rdisc("check", "--format", fmt, path)
        no_crash(result)
        assert result.returncode == 1
    assert "error[E00" in rdisc("check", path).stderr


def test_empty_file_says_there_is_no_robot(rdisc, tmp_path: Path) -> None:
    result = rdisc("check", write(tmp_path, "empty.rdis", ""))
    no_crash(result)
    assert result.returncode == 1
    assert "error[E107]" in result.stderr


# -- the tests' in-process runs ------------------------------------------------------


@pytest.mark.parametrize("argv", [
    ["check", "tests/golden/diagnostics/E102.rdis"],
    ["check", "WIDE"],
    ["check", "--format", "json", "tests/golden/diagnostics/E101.rdis", "tests/golden/diagnostics/W103.rdis"],
    ["check", "-v", CREATE],
    ["explain", "E102"],
    ["check", "--no-such-option", CREATE],
    ["build", "--help"],
], ids=["errors", "wide", "json", "verbose", "explain", "usage", "help"])
def test_a_run_in_process_prints_what_the_command_prints(rdisc, rdisc_process, argv: list[str], tmp_path: Path) -> None:
    """The other tests run these verbs in this process: they must see the command's own exit
    status and bytes, rich's rendering (an emoji, a line past 80 columns) and argparse's wrapping."""
    wide = write(tmp_path, "wide.rdis", CLEAN + 'state s: string = "\U0001F916" $  # ' + "x" * 150 + "\n")
    args = [str(wide) if arg == "WIDE" else arg for arg in argv]
    here, there = rdisc(*args), rdisc_process(*args)
    assert (here.returncode, here.stdout, here.stderr) == (there.returncode, there.stdout, there.stderr)
