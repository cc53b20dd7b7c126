"""`--max-tokens N`: a description past the default token budget is refused with its
diagnostic, and read when the command line raises the budget (every verb that reads one)."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.cli.main import main
from rdisc.compile import MAX_TOKENS, compile_path
from rdisc.syntax.parse import token_count

HEAD = """\
robot large { author "tests" }
connection link: serial { baud 9600 }
primitive ping() on link pack "B" (1)
interface go() { ping() }
input start: Contact -> go()
"""
REFUSED = "error[E005]: the description has more than 200000 tokens, with its imports; this file is not read"


@pytest.fixture(scope="module")
def large(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A clean description just past the default budget, cheap to parse: constants among
    comment lines (a comment is a token; a declaration keeps under its own 20,000)."""
    text = HEAD + "".join(f"const c{i} = {i}\n" + "#\n" * 1000 for i in range(200))
    assert MAX_TOKENS < token_count(text, 10**9) < MAX_TOKENS + 2000
    path = tmp_path_factory.mktemp("large") / "large.rdis"
    path.write_text(text, encoding="utf-8")
    return path


def test_past_the_default_budget_a_description_is_refused(large: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", str(large)]) == 1
    err = capsys.readouterr().err
    assert REFUSED in err and "= help: a larger description you trust is read with `--max-tokens N`" in err


def test_max_tokens_reads_it_for_that_command(large: Path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["check", "--max-tokens", "250000", str(large)]) == 0
    assert "E005" not in capsys.readouterr().err
    assert [d.code for d in compile_path(str(large)).diagnostics.items] == ["E005"]  # the default again
    assert main(["check", "--max-tokens", "200_100", str(large)]) == 1  # a budget it still passes
    assert "more than 200100 tokens" in capsys.readouterr().err


def test_build_takes_it_too(large: Path, tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    out = tmp_path / "large.json"
    assert main(["build", str(large), "-o", str(out)]) == 1 and not out.exists()
    assert main(["build", "--max-tokens", "250000", str(large), "-o", str(out)]) == 0
    assert '"name": "large"' in out.read_text(encoding="utf-8")


@pytest.mark.parametrize("given", ["0", "-5", "many"])
def test_a_budget_that_is_not_a_positive_number_is_a_usage_error(
        given: str, capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as exit_:
        main(["check", "--max-tokens", given, "examples/create.rdis"])
    assert exit_.value.code == 2 and "--max-tokens" in capsys.readouterr().err


def test_a_file_within_the_tokens_left_is_counted_only_when_a_file_after_it_is_read(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """A token is a character or more: a description shorter than the budget is parsed without
    counting its tokens, which an import after it needs counted (what it may still have), exactly."""
    from rdisc import compile as compiling

    counted: list[int] = []

    def count(text: str, most: int) -> int:
        counted.append(len(text))
        return token_count(text, most)

    monkeypatch.setattr(compiling, "token_count", count)
    alone = tmp_path / "alone.rdis"
    alone.write_text(HEAD, encoding="utf-8")
    assert not compile_path(str(alone)).diagnostics.has_errors() and counted == []
    (tmp_path / "more.rdis").write_text("const extra = 1\n", encoding="utf-8")
    main_text = 'import "more.rdis"\n' + HEAD
    importing = tmp_path / "importing.rdis"
    importing.write_text(main_text, encoding="utf-8")
    assert not compile_path(str(importing), max_tokens=1000).diagnostics.has_errors()
    assert counted == [len(main_text)]  # when the import was read; the import, read last, never
    counted.clear()
    budget = token_count(main_text, 10**9) + token_count("const extra = 1\n", 10**9)  # both longer than it
    assert not compile_path(str(importing), max_tokens=budget).diagnostics.has_errors()
    refused = compile_path(str(importing), max_tokens=budget - 1).diagnostics
    assert [d.code for d in refused.items] == ["E005"] and "more.rdis" in refused.items[0].span.path
    assert counted == [len(main_text), len("const extra = 1\n")] * 2
