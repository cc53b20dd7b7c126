"""The language server's answering modules in process (no client): semantic tokens, folding,
references and highlights, an adapter's hover, a quick fix inside a string, and what completion
offers where."""

from __future__ import annotations

from pathlib import Path

import pytest
from lsprotocol import types

from rdisc.editor import actions, completion, hover, navigation, symbols
from rdisc.editor.diagnostics import published
from rdisc.editor.documents import Analysis, Workspace
from tests.editor.test_lsp import BOT, at


def analysed(tmp_path: Path, text: str) -> tuple[Workspace, str, Analysis]:
    path = tmp_path / "bot.rdis"
    workspace = Workspace()
    workspace.open(path.as_uri(), str(path), text, 1)
    found = workspace.analysis(path.as_uri())
    assert found is not None
    return workspace, path.as_uri(), found


def test_semantic_tokens_say_what_each_name_is(tmp_path: Path) -> None:
    _, _, analysis = analysed(tmp_path, BOT)
    data, lines = symbols.semantic_tokens(analysis).data, BOT.splitlines()
    tokens, line, column = [], 0, 0
    for i in range(0, len(data), 5):
        down, across, length, kind, modifiers = data[i : i + 5]
        line, column = line + down, across if down else column + across
        tokens.append((lines[line][column : column + length], symbols.TOKEN_TYPES[kind], modifiers))
    declaration, standard = 1, 4
    assert tokens[:4] == [("bot", "namespace", declaration), ("speed", "variable", declaration),
                          ("link", "namespace", declaration), ("pkt", "type", declaration)]
    assert ("set_speed", "function", 0) in tokens and ("velocity", "parameter", 0) in tokens
    assert tokens[-7:] == [("DifferentialSpeed", "struct", standard), ("drive", "method", 0),
                           ("linear", "property", standard), ("reported", "event", declaration),
                           ("Range", "struct", standard), ("distance", "property", standard), ("speed", "variable", 0)]


def test_folding_references_and_highlights(tmp_path: Path) -> None:
    _, uri, analysis = analysed(tmp_path, BOT)
    assert [(f.start_line, f.end_line) for f in symbols.folding_ranges(analysis)] == [
        (5, 7), (10, 16), (19, 22), (24, 26), (30, 32)]
    place = at(BOT, "state speed", "speed")
    uses = [(p.uri, p.range.start.line) for p in navigation.references(analysis, place, True, [])]
    assert uses == [(uri, 3), (uri, 21), (uri, 31)]
    assert [p.range.start.line for p in navigation.references(analysis, place, False, [])] == [21, 31]
    marks = navigation.highlights(analysis, at(BOT, "set_speed(round", "set_speed"))
    assert [(m.range.start.line, m.kind) for m in marks] == [
        (19, types.DocumentHighlightKind.Write), (25, types.DocumentHighlightKind.Read)]


def test_hover_on_an_adapter_lists_its_fields(tmp_path: Path) -> None:
    _, _, analysis = analysed(tmp_path, BOT)
    found = hover.hover(analysis, None, at(BOT, "output reported: Range", "Range"))
    assert found is not None and isinstance(found.contents, types.MarkupContent)
    assert found.contents.value.startswith("```rdis\nadapter Range\n```\n\n"
                                           "declared in the standard library (stdlib/adapters.rdis)\n\n")
    assert found.contents.value.endswith('fields:\n\n- `distance: float unit "m" ros "range"`: '
                                         "Distance from the sensor to the obstacle.")


@pytest.mark.parametrize(("written", "misspelt", "code"), [
    ('unit "mm/s"', 'unit "mm/z"', "E109"),  # inside its quotes
    ('checksum "xor"', 'checksum "xro"', "E502"),
    ('    pack "<h"', '    pakc "<h"', "E001"),  # a keyword: the parser's did-you-mean
    ("distance = speed", "distance = sped", "E103"),
])
def test_each_did_you_mean_is_a_quick_fix_that_clears_it(tmp_path: Path, written: str, misspelt: str,
                                                          code: str) -> None:
    bad = BOT.replace(written, misspelt)
    workspace, uri, analysis = analysed(tmp_path, bad)
    document = workspace.documents[uri]
    [diagnostic] = published(document, analysis)
    assert diagnostic.code == code
    [fix] = actions.quick_fixes(uri, analysis.source, [diagnostic])
    assert fix.edit is not None and fix.edit.changes is not None
    [edit] = fix.edit.changes[uri]
    lines = bad.splitlines(keepends=True)
    line = lines[edit.range.start.line]
    lines[edit.range.start.line] = line[: edit.range.start.character] + edit.new_text + line[edit.range.end.character :]
    assert "".join(lines) == BOT



@pytest.mark.parametrize(("written", "offered", "not_offered"), [
    ("input cmd: DifferentialSpeed -> drive(|linear)", {"linear", "angular", "speed"}, {"set_speed"}),
    ('value: int in -500..500 unit "m|m/s"', {"mm/s", "rad/s"}, {"speed"}),
    ('checksum "x|or"', {"xor", "crc16-modbus", "crc32"}, {"B"}),
    ('pack "<|h" (value)', {"<", "h", "B"}, {"xor"}),
    ("on link| frame", {"link"}, {"pkt", "speed"}),
    ("frame p|kt(1)", {"pkt"}, {"link"}),
    ("    dist|ance = speed", {"distance"}, {"linear"}),
    ("    set_sp|eed(round", {"set_speed", "drive"}, {"speed"}),
    ("(value) unpack \"<h\" {\n    sp|eed = out[0]", {"speed"}, {"set_speed"}),
    ('on link frame pkt(1)\n    p|ack "<h"', {"pack", "unpack", "format", "reply", "expect"}, {"baud", "speed"}),
    ("\n\ninput| cmd", {"input", "output", "primitive", "frame"}, {"baud", "speed"}),
])
def test_completion_offers_what_the_place_takes(tmp_path: Path, written: str, offered: set[str],
                                                not_offered: set[str]) -> None:
    text = BOT.replace(written.replace("|", ""), written)
    assert text.count("|") == 1, written
    cursor = text.index("|")
    text = text[:cursor] + text[cursor + 1 :]
    _, _, analysis = analysed(tmp_path, text)
    before = text[:cursor]
    place = types.Position(line=before.count("\n"), character=cursor - (before.rfind("\n") + 1))
    labels = {item.label for item in completion.complete(analysis, place).items}
    assert offered <= labels and not labels & not_offered, sorted(labels)


def test_references_and_rename_reach_across_imports(tmp_path: Path) -> None:
    library = 'connection link: serial { baud 9600 }\nprimitive ping() on link pack "B" (1)\n'
    main = 'import "lib.rdis"\nrobot r { author "me" }\ninterface hello() { ping() }\n'
    (tmp_path / "lib.rdis").write_text(library, encoding="utf-8")
    workspace = Workspace()
    for name, text in (("lib.rdis", library), ("main.rdis", main)):
        workspace.open((tmp_path / name).as_uri(), str(tmp_path / name), text, 1)
    lib_uri, main_uri = (tmp_path / "lib.rdis").as_uri(), (tmp_path / "main.rdis").as_uri()
    analysis, other = workspace.analysis(main_uri), workspace.analysis(lib_uri)
    assert analysis is not None and other is not None
    place = at(main, "hello", "ping")
    assert [(p.uri, p.range.start.line) for p in navigation.references(analysis, place, True, [other])] == [
        (lib_uri, 1), (main_uri, 2)]
    edit = navigation.rename(analysis, place, "pong", [other])
    assert edit.changes is not None
    assert {uri: [(e.range.start.line, e.range.start.character, e.new_text) for e in edits]
            for uri, edits in edit.changes.items()} == {lib_uri: [(1, 10, "pong")], main_uri: [(2, 20, "pong")]}
    assert [p.uri for p in navigation.definition(analysis, at(main, "import", "lib.rdis"))] == [lib_uri]
    workspace.change(lib_uri, library.replace("ping", "pong"), 2)
    workspace.check(lib_uri)
    changed = workspace.documents[main_uri].analysis
    assert changed is not None and [d.code for d in changed.compilation.diagnostics.items] == ["E102"]
    assert [d.uri for d in workspace.close(lib_uri)] == [main_uri]  # read from its file again
    again = workspace.documents[main_uri].analysis
    assert again is not None and again.compilation.diagnostics.items == []


def test_a_name_of_the_stdlib_is_not_renamed(tmp_path: Path) -> None:
    _, _, analysis = analysed(tmp_path, BOT)
    with pytest.raises(navigation.Refused, match=r"^`Range` is declared in the standard library"):
        navigation.rename(analysis, at(BOT, "output reported: Range", "Range"), "Distance", [])


def test_while_a_document_has_errors_a_primitive_shows_its_last_good_layout(tmp_path: Path) -> None:
    workspace, uri, _ = analysed(tmp_path, BOT)
    broken = BOT.replace("interface drive(velocity: float)", "interface drive(velocity float)")
    workspace.change(uri, broken, 2)
    analysis = workspace.analysis(uri)
    assert analysis is not None and analysis.compilation.model is None
    found = hover.hover(analysis, workspace.documents[uri].good, at(broken, "primitive set_speed", "set_speed"))
    assert found is not None and isinstance(found.contents, types.MarkupContent)
    assert "wire layout (from the last check without errors):\n\n```\nprimitive set_speed(value: int in -500..500) " \
           "on link, frame pkt(1)\n  request: 6 bytes\n" in found.contents.value
    alone = hover.hover(analysis, None, at(broken, "primitive set_speed", "set_speed"))
    assert alone is not None and isinstance(alone.contents, types.MarkupContent)
    assert alone.contents.value.endswith("*the wire layout is shown once the description checks without errors*")


def test_after_typing_at_the_top_every_answer_is_where_a_fresh_check_puts_it(tmp_path: Path) -> None:
    """What only moved is kept, its spans moved in place: the diagnostics, names, references, rename
    and definitions of the moved text are a fresh workspace's, each place exact."""
    misspelt = BOT.replace("set_speed(round", "set_sped(round")
    workspace, uri, _ = analysed(tmp_path, misspelt)
    for version, text in enumerate(("# moved\n" + misspelt, "\n\n# moved again\n" + misspelt, misspelt), start=2):
        workspace.change(uri, text, version)
        kept = workspace.analysis(uri)
        fresh = Workspace()
        fresh.open(uri, str(tmp_path / "bot.rdis"), text, version)
        made = fresh.analysis(uri)
        assert kept is not None and made is not None
        document = workspace.documents[uri]
        assert document.parser.reused > 5 and document.memo.reused > 0  # moved, and kept
        assert published(document, kept) == published(fresh.documents[uri], made)
        assert [d.code for d in published(document, kept)] == ["E102"]
        assert symbols.semantic_tokens(kept) == symbols.semantic_tokens(made)
        assert symbols.document_symbols(kept) == symbols.document_symbols(made)
        for place in (at(text, "state speed", "speed"), at(text, "set_sped(round", "velocity"),
                      at(text, "output reported: Range", "Range"), at(text, "primitive set_speed", "set_speed")):
            assert navigation.references(kept, place, True, []) == navigation.references(made, place, True, [])
            assert navigation.highlights(kept, place) == navigation.highlights(made, place)
            assert navigation.definition(kept, place) == navigation.definition(made, place)
        place = at(text, "state speed", "speed")
        assert navigation.rename(kept, place, "pace", []) == navigation.rename(made, place, "pace", [])
        assert navigation.references(kept, place, True, [])[0].range.start.line == text[:text.index("state speed")].count("\n")
