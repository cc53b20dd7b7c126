"""When the language server checks (rdisc.editor.checks), in process: at once, one check at a
time, the changes made during a check gathered into one next check of the latest text, and a
stale result never published."""

from __future__ import annotations

from pathlib import Path

import pytest

from rdisc.editor.checks import Checker
from rdisc.editor.diagnostics import published
from rdisc.editor.documents import Analysis, Document, Job, Workspace
from tests.editor.test_lsp import BOT


@pytest.mark.asyncio
async def test_changes_made_during_a_check_are_checked_once_and_the_stale_result_is_dropped(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    checked: list[str] = []
    run = Job.run

    def counted(job: Job) -> Analysis:
        checked.append(job.text)
        return run(job)

    monkeypatch.setattr(Job, "run", counted)
    workspace = Workspace()
    publishes: list[tuple[int | None, list[str]]] = []

    def publish(document: Document) -> None:
        assert document.analysis is not None
        publishes.append((document.version, [d.message for d in published(document, document.analysis)]))

    checker = Checker(workspace, publish)
    path = tmp_path / "bot.rdis"
    uri = path.as_uri()
    workspace.open(uri, str(path), BOT, 1)
    checker.request(uri)
    assert checker.running is not None  # started at once, no pause waited for
    texts = [BOT.replace("set_speed(round", f"set_speed{n}(round") for n in range(2, 7)]
    for version, text in enumerate(texts, 2):  # all made while the first check runs
        workspace.change(uri, text, version)
        checker.request(uri)
    analysis = await checker.analysis(uri)
    assert checked == [BOT, texts[-1]]
    assert analysis is not None and analysis is workspace.documents[uri].analysis
    assert publishes == [(6, ["unknown primitive or interface `set_speed6`"])]  # not the first check's: stale


@pytest.mark.asyncio
async def test_a_question_waits_for_the_check_of_the_text_it_is_about(tmp_path: Path) -> None:
    workspace = Workspace()
    checker = Checker(workspace, lambda document: None)
    lib, main = tmp_path / "lib.rdis", tmp_path / "main.rdis"
    library = 'connection link: serial { baud 9600 }\nprimitive ping() on link pack "B" (1)\n'
    lib.write_text(library, encoding="utf-8")
    workspace.open(lib.as_uri(), str(lib), library, 1)
    workspace.open(main.as_uri(), str(main), 'import "lib.rdis"\nrobot r { author "me" }\ninterface hello() { ping() }\n', 1)
    checker.request(lib.as_uri())
    checker.request(main.as_uri())
    first = await checker.analysis(main.as_uri())
    assert first is not None and first.compilation.diagnostics.items == []
    workspace.change(lib.as_uri(), library.replace("ping", "pong"), 2)
    checker.request(lib.as_uri())
    await checker.analysis(lib.as_uri())
    assert workspace.documents[main.as_uri()].analysis is None  # the import checked: its importer's check is dropped
    again = await checker.analysis(main.as_uri())
    assert again is not None and [d.code for d in again.compilation.diagnostics.items] == ["E102"]
    assert await checker.analysis((tmp_path / "closed.rdis").as_uri()) is None
