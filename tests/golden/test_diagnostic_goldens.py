"""One small description per diagnostic code, with its renderings as goldens.

For every input `diagnostics/<CODE>.rdis` (`E008.json`: a JSON description) the
test runs the real command, from the repository root with a relative path:

- `rdisc check FILE` → stderr, the text for people, golden `<CODE>.txt`;
- `rdisc check --format json FILE...` of all inputs at once → stdout, the
  LSP-shaped JSON for editors, split by file: golden `<CODE>.lsp.json`
  (absolute `file://` URIs of related locations are rewritten to
  `file:///<repo>/...` so the golden is the same on every machine).

Each input must produce at least one diagnostic of its own code, and the set of
inputs must cover every code of the registry. Refresh with `--update-goldens`
and read the diff: the text must say in words what is wrong and where.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest

from rdisc.diagnostics.codes import CODES

REPO = Path(__file__).resolve().parents[2]
HERE = Path(__file__).resolve().parent / "diagnostics"
INPUTS = sorted(p for p in HERE.iterdir() if re.fullmatch(r"[EW]\d{3}\.(rdis|json)", p.name))
IDS = [p.name.split(".")[0] for p in INPUTS]


def relative(path: Path) -> str:
    return path.relative_to(REPO).as_posix()


def normalise_text(text: str) -> str:
    """Absolute paths under the repository (the stdlib's) become relative."""
    return text.replace(str(REPO) + os.sep, "")


def normalise_lsp(items: list[dict]) -> list[dict]:
    prefix = REPO.as_uri() + "/"
    for item in items:
        for related in item["relatedInformation"]:
            uri = related["location"]["uri"]
            if uri.startswith(prefix):
                related["location"]["uri"] = "file:///<repo>/" + uri[len(prefix):]
    return items


@pytest.fixture(scope="session")
def runs(rdisc) -> dict[str, object]:
    """Each input's text rendering, one `rdisc check` each."""
    return {code: rdisc("check", relative(path)) for code, path in zip(IDS, INPUTS)}


@pytest.fixture(scope="session")
def lsp(rdisc) -> dict[str, list[dict]]:
    """Every input through one `rdisc check --format json`, its array split by `file`.

    The only diagnostic without a file is the one about the unreadable E006 input."""
    result = rdisc("check", "--format", "json", *map(relative, INPUTS))
    assert "Traceback" not in result.stderr
    assert result.returncode == 2  # E006: a file that cannot be read
    by_file: dict[str, list[dict]] = {code: [] for code in IDS}
    names = {relative(path): code for code, path in zip(IDS, INPUTS)}
    for item in json.loads(result.stdout):
        by_file["E006" if item["file"] is None else names[item["file"]]].append(item)
    return by_file


def test_every_code_has_an_input() -> None:
    assert set(IDS) == set(CODES), "add an input for each new code (or remove the input of a dropped one)"


@pytest.mark.parametrize("code", IDS)
def test_text_rendering(code: str, runs, golden) -> None:
    result = runs[code]
    assert "Traceback" not in result.stderr
    assert "internal error" not in result.stderr
    assert result.stdout == ""
    expected_exit = 0 if code.startswith("W") else 2 if code == "E006" else 1
    assert result.returncode == expected_exit, result.stderr
    assert re.search(rf"^(error|warning)\[{code}\]: ", result.stderr, re.MULTILINE), result.stderr
    golden.check(HERE / f"{code}.txt", normalise_text(result.stderr))


@pytest.mark.parametrize("code", IDS)
def test_lsp_rendering(code: str, lsp, golden) -> None:
    items = lsp[code]
    assert code in {item["code"] for item in items}
    for item in items:
        assert item["source"] == "rdisc"
        assert item["severity"] == (1 if item["code"].startswith("E") else 2)
        assert item["data"]["name"] == CODES[item["code"]].name
    golden.check(HERE / f"{code}.lsp.json", json.dumps(normalise_lsp(items), indent=2, ensure_ascii=False) + "\n")


@pytest.mark.parametrize("code", IDS)
def test_lsp_matches_text(code: str, runs, lsp) -> None:
    """Both renderings carry the same diagnostics, in the same order."""
    headers = re.findall(r"^(?:error|warning)\[(\w+)\]: (.*)$", runs[code].stderr, re.MULTILINE)
    assert headers == [(item["code"], item["message"]) for item in lsp[code]]
