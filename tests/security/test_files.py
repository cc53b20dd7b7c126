"""Files a description names or a user gives: imports that cannot be read are diagnostics,
not tracebacks; an input that is not a regular file (a FIFO, a device) is refused without
blocking; no output is written over a file it was made from."""

from __future__ import annotations

import os
import shutil
from pathlib import Path

import pytest
from conftest import run_rdisc

REPO = Path(__file__).resolve().parents[2]


@pytest.mark.parametrize(("name", "setup", "message"), [
    ("loop.rdis", "loop", "error[E007]: cannot import `loop.rdis`: Symlink loop from"),
    ("a\\0b.rdis", None, "error[E007]: cannot import `a\\x00b.rdis`: embedded null byte"),
    ("a" * 300 + ".rdis", None, "error[E007]: cannot import `aaaaaaaaaaaaaaaaaaaaa...`: File name too long"),
])
def test_imports_that_cannot_be_read_are_diagnostics(tmp_path: Path, name: str, setup: str | None,
                                                      message: str) -> None:
    if setup == "loop":
        (tmp_path / "loop.rdis").symlink_to("other.rdis")
        (tmp_path / "other.rdis").symlink_to("loop.rdis")
    source = tmp_path / "main.rdis"
    source.write_text(f'robot r {{ author "tests" }}\nimport "{name}"\n', encoding="utf-8")
    result = run_rdisc("check", source)
    assert result.returncode == 1
    assert result.stderr.startswith(message), result.stderr
    assert "internal error" not in result.stderr


def test_a_fifo_is_refused_without_blocking(tmp_path: Path) -> None:
    fifo = tmp_path / "description.rdis"
    os.mkfifo(fifo)
    result = run_rdisc("check", fifo)  # with no writer, an open for reading would wait for ever
    assert result.returncode == 2
    assert result.stderr.startswith(f"error[E006]: cannot read {fifo}: not a regular file\n"), result.stderr


@pytest.mark.parametrize("verb", ["build", "dump", "emit-python", "emit-ros", "emit-ros2"])
def test_no_output_over_the_description_or_its_imports(tmp_path: Path, verb: str) -> None:
    source = tmp_path / "create.rdis"
    shutil.copy(REPO / "examples" / "create.rdis", source)
    before = source.read_bytes()
    (tmp_path / "alias.rdis").symlink_to(source)
    for target in (source, tmp_path / "alias.rdis", tmp_path / "." / "create.rdis"):
        result = run_rdisc(verb, source, "-o", target)
        assert result.returncode == 2, result.stderr
        assert result.stderr.endswith(f"rdisc: will not write {target}: it is {source}, which this was made "
                                      "from\n"), result.stderr
        assert source.read_bytes() == before


def test_import_will_not_write_over_its_json(tmp_path: Path) -> None:
    source = tmp_path / "thesis.json"
    shutil.copy(REPO / "tests" / "syntax" / "data" / "thesis_create.json", source)
    before = source.read_bytes()
    result = run_rdisc("import", source, "-o", source)
    assert result.returncode == 2
    assert source.read_bytes() == before


def test_a_description_past_the_token_budget_is_refused_before_the_parser_sees_it(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    """Parsing costs time in proportion to tokens: each imported file counts against one
    budget for the description, and a file past it is not parsed (nor is anything
    reported missing from it)."""
    from rdisc import compile as compile_module
    from rdisc.syntax.parse import token_count

    part = "\n".join(f"const c{i} = {i}" for i in range(compile_module.MAX_TOKENS // 10)) + "\n"
    assert token_count(part, 10**9) == compile_module.MAX_TOKENS * 4 // 10  # two fit, three do not
    (tmp_path / "one.rdis").write_text(part, encoding="utf-8")
    (tmp_path / "two.rdis").write_text(part.replace("const c", "const d"), encoding="utf-8")
    (tmp_path / "three.rdis").write_text(part.replace("const c", "const e"), encoding="utf-8")
    main = tmp_path / "main.rdis"
    main.write_text('robot r { author "tests" }\nimport "one.rdis"\nimport "two.rdis"\nimport "three.rdis"\n',
                    encoding="utf-8")
    parsed: list[str] = []
    real_parse = compile_module.parse

    def counting_parse(path: str, text: str, diagnostics):
        parsed.append(Path(path).name)
        return real_parse(path, text, diagnostics)

    monkeypatch.setattr(compile_module, "parse", counting_parse)
    compilation = compile_module.compile_path(str(main))
    assert parsed == ["main.rdis", "adapters.rdis", "one.rdis", "two.rdis"]  # and the standard adapters
    assert [(d.code, d.message) for d in compilation.diagnostics.items] == [
        ("E005", "the description has more than 200000 tokens, with its imports; this file is not read")]
    assert compilation.diagnostics.items[0].span.path == str(tmp_path / "three.rdis")
