"""`rdisc lsp` end to end: a real LSP client (pytest-lsp) over stdio against `python -m rdisc lsp`,
one server for the module, each test on documents of its own."""

from __future__ import annotations

import asyncio
import os
import sys
from collections.abc import AsyncIterator
from pathlib import Path

import pytest
import pytest_lsp
from lsprotocol import types
from pygls.exceptions import JsonRpcException
from pytest_lsp import ClientServerConfig, LanguageClient

ROOT = Path(__file__).resolve().parents[2]
STDLIB = ROOT / "stdlib" / "adapters.rdis"

BOT = '''robot bot { author "me" }

/// The last speed the device reported.
state speed: int = 0

connection link: serial {
    baud 115200
}

/// A packet: header, id, length, payload and an XOR of them.
frame pkt(id: int in 0..255) {
    header "\\xAA"
    field id "B" = id
    length "B" = payload
    payload
    checksum "xor" "B" over header .. payload
}

/// Set the wheel speed.
primitive set_speed(value: int in -500..500 unit "mm/s") on link frame pkt(1)
    pack "<h" (value) unpack "<h" {
    speed = out[0]
}

interface drive(velocity: float) triggers reported {
    set_speed(round(velocity * 1000))
}

input cmd: DifferentialSpeed -> drive(linear)

output reported: Range {
    distance = speed / 1000
}
'''

pytestmark = pytest.mark.asyncio(loop_scope="module")


@pytest_lsp.fixture(scope="module", config=ClientServerConfig(
    server_command=[sys.executable, "-m", "rdisc", "lsp"],
    server_env={**os.environ, "PYTHONPATH": str(ROOT)}))
async def client(lsp_client: LanguageClient) -> AsyncIterator[None]:
    await lsp_client.initialize_session(types.InitializeParams(capabilities=types.ClientCapabilities()))
    yield
    await lsp_client.shutdown_session()


async def opened(client: LanguageClient, folder: Path, name: str, text: str) -> str:
    """Open a document (its file written too, as an editor's would be) and wait for its diagnostics."""
    path = folder / name
    path.write_text(text, encoding="utf-8")
    uri = path.resolve().as_uri()
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        text_document=types.TextDocumentItem(uri=uri, language_id="rdis", version=1, text=text)))
    while uri not in client.diagnostics:
        await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    return uri


async def changed(client: LanguageClient, uri: str, text: str, version: int) -> list[types.Diagnostic]:
    """Send the document's new text and wait for the diagnostics of it (after the server's pause)."""
    client.diagnostics.pop(uri, None)
    client.text_document_did_change(types.DidChangeTextDocumentParams(
        text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
        content_changes=[types.TextDocumentContentChangeWholeDocument(text=text)]))
    while uri not in client.diagnostics:
        await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    return list(client.diagnostics[uri])


def at(text: str, line_with: str, word: str, nth: int = 0) -> types.Position:
    """The position of `word` in the `nth` line containing `line_with`."""
    lines = [(n, line) for n, line in enumerate(text.splitlines()) if line_with in line]
    n, line = lines[nth]
    return types.Position(line=n, character=line.index(word))


def applied(text: str, edits: list[types.TextEdit]) -> str:
    """The text with the edits made (from the last, so earlier places stay put)."""
    lines = text.splitlines(keepends=True)
    starts = [0]
    for line in lines:
        starts.append(starts[-1] + len(line))
    for edit in sorted(edits, key=lambda e: (e.range.start.line, e.range.start.character), reverse=True):
        start = starts[edit.range.start.line] + edit.range.start.character
        end = starts[edit.range.end.line] + edit.range.end.character
        text = text[:start] + edit.new_text + text[end:]
    return text


async def test_a_misspelt_primitive_is_reported_on_its_line_and_its_quick_fix_clears_it(
        client: LanguageClient, tmp_path: Path) -> None:
    bad = BOT.replace("    set_speed(round", "    set_sped(round")
    uri = await opened(client, tmp_path, "bad.rdis", bad)
    [diagnostic] = client.diagnostics[uri]
    assert (diagnostic.code, diagnostic.range.start, diagnostic.message) == (
        "E102", at(bad, "set_sped(round", "set_sped"), "unknown primitive or interface `set_sped`")
    actions = await client.text_document_code_action_async(types.CodeActionParams(
        text_document=types.TextDocumentIdentifier(uri=uri), range=diagnostic.range,
        context=types.CodeActionContext(diagnostics=[diagnostic])))
    assert actions is not None and len(actions) == 1
    [action] = actions
    assert isinstance(action, types.CodeAction) and action.edit is not None and action.edit.changes is not None
    assert action.title == "Change to `set_speed`"
    fixed = applied(bad, list(action.edit.changes[uri]))
    assert fixed == BOT
    assert await changed(client, uri, fixed, 2) == []


async def test_hover_on_a_framed_primitive_shows_its_bytes_and_doc(client: LanguageClient, tmp_path: Path) -> None:
    uri = await opened(client, tmp_path, "hover.rdis", BOT)
    found = await client.text_document_hover_async(types.HoverParams(
        text_document=types.TextDocumentIdentifier(uri=uri), position=at(BOT, "set_speed(round", "set_speed")))
    assert found is not None and isinstance(found.contents, types.MarkupContent)
    text = found.contents.value
    assert 'primitive set_speed(value: int in -500..500 unit "mm/s")' in text
    assert "Set the wheel speed." in text
    assert "  request: 6 bytes\n  offset  size  kind                  value\n" \
           "       0     1  header                AA\n" in text
    assert "       3     2  payload s16 LE        value\n" in text
    param = await client.text_document_hover_async(types.HoverParams(
        text_document=types.TextDocumentIdentifier(uri=uri), position=at(BOT, '(value)', "value")))
    assert param is not None and isinstance(param.contents, types.MarkupContent)
    assert param.contents.value.startswith('```rdis\nvalue: int in -500..500 unit "mm/s"\n```\n\n'
                                           "parameter of primitive `set_speed`")


async def test_definition_goes_from_a_call_to_its_primitive_and_into_the_stdlib(
        client: LanguageClient, tmp_path: Path) -> None:
    uri = await opened(client, tmp_path, "definition.rdis", BOT)
    document = types.TextDocumentIdentifier(uri=uri)
    found = await client.text_document_definition_async(types.DefinitionParams(
        text_document=document, position=at(BOT, "set_speed(round", "set_speed")))
    assert isinstance(found, list) and [(f.uri, f.range.start) for f in found] == [
        (uri, at(BOT, "primitive set_speed", "set_speed"))]
    stdlib = STDLIB.read_text(encoding="utf-8")
    for word, line_with in (("DifferentialSpeed", "adapter DifferentialSpeed"), ("linear", "linear: float")):
        found = await client.text_document_definition_async(types.DefinitionParams(
            text_document=document, position=at(BOT, "input cmd", word)))
        assert isinstance(found, list) and [(f.uri, f.range.start) for f in found] == [
            (STDLIB.resolve().as_uri(), at(stdlib, line_with, word))]


async def test_rename_of_a_state_variable_edits_every_use_and_is_refused_for_a_keyword_or_a_taken_name(
        client: LanguageClient, tmp_path: Path) -> None:
    uri = await opened(client, tmp_path, "rename.rdis", BOT)
    document = types.TextDocumentIdentifier(uri=uri)
    place = at(BOT, "distance = speed", "speed")
    edit = await client.text_document_rename_async(types.RenameParams(
        text_document=document, position=place, new_name="reported_speed"))
    assert edit is not None and edit.changes is not None and list(edit.changes) == [uri]
    renamed = applied(BOT, list(edit.changes[uri]))
    assert len(edit.changes[uri]) == 3
    assert renamed == BOT.replace("state speed", "state reported_speed").replace(
        "    speed = out", "    reported_speed = out").replace("= speed /", "= reported_speed /")
    assert await changed(client, uri, renamed, 2) == []
    for word, new_name, reason in (
            ("reported_speed", "if", "`if` is a keyword and cannot name a state variable"),
            ("reported_speed", "round", "`round` is a built-in function and cannot name a state variable"),
            ("set_speed", "drive", "`drive` is already the name of interface `drive` (line 25)")):
        with pytest.raises(JsonRpcException) as refused:
            await client.text_document_rename_async(types.RenameParams(
                text_document=document, position=at(renamed, f" {word}", word), new_name=new_name))
        assert (refused.value.code, refused.value.message) == (types.LSPErrorCodes.RequestFailed, reason)


async def test_completion_inside_a_pack_list_offers_the_parameters(client: LanguageClient, tmp_path: Path) -> None:
    uri = await opened(client, tmp_path, "complete.rdis", BOT)
    typing = BOT.replace('pack "<h" (value)', 'pack "<h" (va')
    await changed(client, uri, typing, 2)
    cursor = at(typing, '"<h" (va', "(va")
    found = await client.text_document_completion_async(types.CompletionParams(
        text_document=types.TextDocumentIdentifier(uri=uri),
        position=types.Position(line=cursor.line, character=cursor.character + 3)))
    assert isinstance(found, types.CompletionList)
    offered = {item.label: item.detail for item in found.items}
    assert offered["value"] == "parameter of set_speed" and offered["speed"] == "state variable"
    assert "drive" not in offered  # an interface is no value


async def test_a_document_with_a_syntax_error_still_has_symbols_and_hovers(
        client: LanguageClient, tmp_path: Path) -> None:
    broken = BOT.replace("interface drive(velocity: float)", "interface drive(velocity float)")
    uri = await opened(client, tmp_path, "broken.rdis", broken)
    assert [d.code for d in client.diagnostics[uri]] == ["E001"]
    found = await client.text_document_document_symbol_async(types.DocumentSymbolParams(
        text_document=types.TextDocumentIdentifier(uri=uri)))
    assert found is not None
    assert [s.name for s in found] == ["bot", "speed", "link", "pkt", "set_speed", "cmd", "reported"]
    hovered = await client.text_document_hover_async(types.HoverParams(
        text_document=types.TextDocumentIdentifier(uri=uri), position=at(broken, "state speed", "speed")))
    assert hovered is not None and isinstance(hovered.contents, types.MarkupContent)
    assert hovered.contents.value == "```rdis\nstate speed: int = 0\n```\n\nThe last speed the device reported."


HOSTILE = {  # each with the code of its diagnostic: refused within the compiler's limits
    "giant.rdis": ("robot giant { author \"x\" }\n" + "const C = 1\n" * 55_000, "E005"),
    "nested.rdis": ("robot nested { author \"x\" }\nconst C = " + "(" * 1000 + "1" + ")" * 1000 + "\n", "E005"),
    "redos.rdis": ('robot redos { author "x" }\nconnection c: serial { baud 9600 }\n'
                   'primitive p() on c format "x" () regex "(a+)+$"\n' + "# " + "a" * 60000 + "!\n", "E304"),
    "wide.rdis": ('robot wide { author "x" }\nconst Bee = 1\nconst A = [' + ", ".join(["Bee"] * 6000) + "]\n",
                  "E404"),  # one line of many names: each one's column
}


async def test_hostile_documents_leave_the_server_answering(client: LanguageClient, tmp_path: Path) -> None:
    for name, (text, code) in HOSTILE.items():
        uri = await opened(client, tmp_path, name, text)
        assert [d.code for d in client.diagnostics[uri]] == [code]
        found = await client.text_document_document_symbol_async(types.DocumentSymbolParams(
            text_document=types.TextDocumentIdentifier(uri=uri)))
        assert found is not None
        colours = await client.text_document_semantic_tokens_full_async(types.SemanticTokensParams(
            text_document=types.TextDocumentIdentifier(uri=uri)))
        assert colours is not None and (len(colours.data) == 5 * 6003 or name != "wide.rdis")
        last = text.splitlines()[-1]
        for place in (types.Position(line=1, character=10), types.Position(line=text.count("\n") - 1,
                                                                           character=len(last))):
            await client.text_document_completion_async(types.CompletionParams(
                text_document=types.TextDocumentIdentifier(uri=uri), position=place))
    uri = await opened(client, tmp_path, "after.rdis", BOT)
    assert list(client.diagnostics[uri]) == []


async def test_a_change_to_an_imported_file_rechecks_the_open_files_importing_it(
        client: LanguageClient, tmp_path: Path) -> None:
    library = 'connection link: serial { baud 9600 }\nprimitive ping() on link pack "B" (1)\n'
    lib = await opened(client, tmp_path, "lib.rdis", library)
    main = await opened(client, tmp_path, "main.rdis",
                        'import "lib.rdis"\nrobot r { author "me" }\ninterface hello() { ping() }\n')
    assert list(client.diagnostics[main]) == []
    client.diagnostics.pop(main)
    await changed(client, lib, library.replace("ping", "pong"), 2)  # not saved: the editor's text is read
    while main not in client.diagnostics:
        await client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    assert [(d.code, d.range.start.line, d.message) for d in client.diagnostics[main]] == [
        ("E102", 2, "unknown primitive or interface `ping`")]


async def test_rapid_changes_end_with_the_diagnostics_of_the_last_text(client: LanguageClient, tmp_path: Path) -> None:
    uri = await opened(client, tmp_path, "rapid.rdis", BOT)
    client.diagnostics.pop(uri)
    texts = {version: BOT.replace("set_speed(round", f"set_speed{version}(round") for version in range(2, 12)}
    for version, text in texts.items():  # sent at once: the server is checking the first while the rest arrive
        client.text_document_did_change(types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text=text)]))
    seen: list[int] = []  # the versions whose diagnostics were published, in order
    while not seen or seen[-1] != 11:
        while uri not in client.diagnostics:
            await asyncio.wait_for(client.wait_for_notification(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS), 60)
        (found,) = client.diagnostics.pop(uri)
        seen.append(int(found.message.removeprefix("unknown primitive or interface `set_speed").rstrip("`")))
        assert (found.code, found.range.start.line) == ("E102", at(texts[11], "set_speed11(", "set_speed").line)
    assert seen == sorted(set(seen))  # a stale check's diagnostics never come after a newer one's


async def formatted_by(client: LanguageClient, uri: str, where: types.Range | None = None) -> list[types.TextEdit]:
    document = types.TextDocumentIdentifier(uri=uri)
    options = types.FormattingOptions(tab_size=4, insert_spaces=True)
    if where is None:
        edits = await client.text_document_formatting_async(
            types.DocumentFormattingParams(text_document=document, options=options))
    else:
        edits = await client.text_document_range_formatting_async(
            types.DocumentRangeFormattingParams(text_document=document, range=where, options=options))
    assert edits is not None
    return list(edits)


def lines_of(edits: list[types.TextEdit]) -> list[tuple[int, int]]:
    return [(edit.range.start.line, edit.range.end.line) for edit in edits]


async def test_formatting_returns_edits_of_only_the_changed_lines_that_produce_rdisc_fmts_text(
        client: LanguageClient, tmp_path: Path) -> None:
    from rdisc.format import format_text

    canonical = format_text(BOT)
    messy = canonical.replace("state speed: int = 0", "state   speed:int=0").replace(
        "    baud 115200", "  baud   115200")
    uri = await opened(client, tmp_path, "messy.rdis", messy)
    edits = await formatted_by(client, uri)
    state, baud = (canonical.splitlines().index(line) for line in ("state speed: int = 0", "    baud 115200"))
    assert lines_of(edits) == [(state, state + 1), (baud, baud + 1)]  # the two changed lines, each alone
    assert applied(messy, edits) == canonical
    uri = await opened(client, tmp_path, "whole.rdis", BOT)
    assert applied(BOT, await formatted_by(client, uri)) == canonical
    assert await formatted_by(client, await opened(client, tmp_path, "done.rdis", canonical)) == []


async def test_range_formatting_touches_only_the_declarations_in_the_range(
        client: LanguageClient, tmp_path: Path) -> None:
    messy = "enum Op { ping = 1,\n read = 2 }\nconst   BROADCAST=0xFE\n\nconst   OTHER=0xFF   # kept\n"
    uri = await opened(client, tmp_path, "range.rdis", messy)
    inside_other = types.Range(start=types.Position(line=4, character=2), end=types.Position(line=4, character=4))
    edits = await formatted_by(client, uri, inside_other)
    assert applied(messy, edits) == (
        "enum Op { ping = 1,\n read = 2 }\nconst   BROADCAST=0xFE\n\nconst OTHER = 0xFF  # kept\n")
    enum_to_const = types.Range(start=types.Position(line=1, character=5), end=types.Position(line=2, character=0))
    assert applied(messy, await formatted_by(client, uri, enum_to_const)) == (
        "enum Op {\n    ping = 1,\n    read = 2,\n}\nconst BROADCAST = 0xFE\n\nconst   OTHER=0xFF   # kept\n")
    blank_line = types.Range(start=types.Position(line=3, character=0), end=types.Position(line=3, character=0))
    assert await formatted_by(client, uri, blank_line) == []


async def test_a_document_that_does_not_parse_gets_no_formatting_edits_and_no_error(
        client: LanguageClient, tmp_path: Path) -> None:
    broken = "const   A=1\nenum Op { ping = \n"
    uri = await opened(client, tmp_path, "broken.rdis", broken)
    assert await formatted_by(client, uri) == []
    whole = types.Range(start=types.Position(line=0, character=0), end=types.Position(line=2, character=0))
    assert await formatted_by(client, uri, whole) == []
