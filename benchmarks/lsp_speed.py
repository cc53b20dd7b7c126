"""How fast `rdisc lsp` answers, measured through a real LSP client over stdio (pygls's), against
`python -m rdisc lsp` in a process of its own, on a generated description of about 1,000 lines:

- a change re-checked and its diagnostics published: from sending the change to the diagnostics
  arriving (target 20 ms), for a change of a line keeping its length, and for a character more
  near the top, which moves every declaration after it;
- hover on a call of a primitive, and completion inside a `pack` list (target 10 ms each);

and, in this process, what the check alone costs (rdisc.compile.compile_text), to tell the
compiler's share from the server's: of the whole file, and after the change as the editor checks
it, parsing again only the declaration changed (rdisc.syntax.incremental) and checking again only
the primitives and interfaces it touched (rdisc.semantics.check.memo); and after a character more
near the top, where every declaration after it moves and is taken again as it was, its spans moved in place.

    python benchmarks/lsp_speed.py [--runs N]
"""

from __future__ import annotations

import argparse
import asyncio
import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

from lsprotocol import types
from pygls.lsp.client import LanguageClient

ROOT = Path(__file__).resolve().parent.parent
CHANGE_TARGET_MS = 20.0
ANSWER_TARGET_MS = 10.0


def description(blocks: int = 165) -> str:
    """About 1,000 lines: a state variable, a connection, and `blocks` primitives each with an
    interface calling it."""
    lines = ['robot big { author "lsp_speed" }', "", "state last: int = 0", "",
             "connection link: serial {", "    baud 115200", "}", ""]
    for i in range(blocks):
        lines += [f"/// Set register {i}.",
                  (f'primitive set_{i}(value: int in 0..1000 unit "mm") on link pack ">BH" ({i % 200}, value) '
                   'unpack "B" {'), "    last = out[0]", "}",
                  f"interface move_{i}(value: float) {{ set_{i}(round(value * 1000)) }}", ""]
    return "\n".join(lines) + "\n"


def median_ms(samples: list[float]) -> float:
    return statistics.median(samples) * 1000


async def measure(runs: int) -> dict[str, float]:
    text = description()
    folder = Path(tempfile.mkdtemp(prefix="rdisc-lsp-speed-"))
    path = folder / "big.rdis"
    path.write_text(text, encoding="utf-8")
    uri = path.resolve().as_uri()
    arrived: asyncio.Queue[float] = asyncio.Queue()
    client = LanguageClient("lsp_speed", "1")

    @client.feature(types.TEXT_DOCUMENT_PUBLISH_DIAGNOSTICS)
    def published(params: types.PublishDiagnosticsParams) -> None:
        arrived.put_nowait(time.perf_counter())

    environment = {**os.environ, "PYTHONPATH": str(ROOT)}
    await client.start_io(sys.executable, "-m", "rdisc", "lsp", env=environment)
    await client.initialize_async(types.InitializeParams(capabilities=types.ClientCapabilities()))
    client.initialized(types.InitializedParams())
    client.text_document_did_open(types.DidOpenTextDocumentParams(
        text_document=types.TextDocumentItem(uri=uri, language_id="rdis", version=1, text=text)))
    await arrived.get()
    document = types.TextDocumentIdentifier(uri=uri)
    lines = text.splitlines()
    call_line = next(n for n, line in enumerate(lines) if "set_80(round" in line)
    pack_line = next(n for n, line in enumerate(lines) if "primitive set_80(" in line)

    changes = []
    for run in range(runs):
        edited = text.replace("0..1000", f"0..{1001 + run}", 1)
        start = time.perf_counter()
        client.text_document_did_change(types.DidChangeTextDocumentParams(
            text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=run + 2),
            content_changes=[types.TextDocumentContentChangeWholeDocument(text=edited)]))
        changes.append(await arrived.get() - start)

    moves, version = [], runs + 2
    for run in range(runs):  # a character more, then back: what follows moves each time
        for edited, times in ((text.replace("0..1000", f"0..{10001 + run}", 1), moves), (text, None)):
            version += 1
            start = time.perf_counter()
            client.text_document_did_change(types.DidChangeTextDocumentParams(
                text_document=types.VersionedTextDocumentIdentifier(uri=uri, version=version),
                content_changes=[types.TextDocumentContentChangeWholeDocument(text=edited)]))
            at = await arrived.get()
            if times is not None:
                times.append(at - start)

    hovers, completions = [], []
    for _ in range(runs):
        start = time.perf_counter()
        await client.text_document_hover_async(types.HoverParams(
            text_document=document, position=types.Position(line=call_line, character=lines[call_line].index("set_80"))))
        hovers.append(time.perf_counter() - start)
        start = time.perf_counter()
        await client.text_document_completion_async(types.CompletionParams(
            text_document=document,
            position=types.Position(line=pack_line, character=lines[pack_line].index(", value)") + 2)))
        completions.append(time.perf_counter() - start)

    await client.shutdown_async(None)
    client.exit(None)
    await client.stop()

    from rdisc.compile import compile_text
    from rdisc.semantics.check.memo import Memo
    from rdisc.syntax.incremental import Reparser

    checks, edited_checks, moved_checks = [], [], []
    reparser, memo = Reparser(), Memo()
    compile_text(str(path), text, parser=reparser, memo=memo)
    for run in range(runs):
        start = time.perf_counter()
        compile_text(str(path), text)
        checks.append(time.perf_counter() - start)
        edited = text.replace("0..1000", f"0..{1001 + run}", 1)
        start = time.perf_counter()
        compile_text(str(path), edited, parser=reparser, memo=memo)
        edited_checks.append(time.perf_counter() - start)
        longer = text.replace("0..1000", f"0..{10001 + run}", 1)  # one character more: the rest moves
        start = time.perf_counter()
        compile_text(str(path), longer, parser=reparser, memo=memo)
        moved_checks.append(time.perf_counter() - start)
        compile_text(str(path), text, parser=reparser, memo=memo)
    return {"moved": median_ms(moved_checks), "change": median_ms(changes), "moves": median_ms(moves), "hover": median_ms(hovers), "completion": median_ms(completions),
            "check": median_ms(checks), "edited": median_ms(edited_checks), "lines": float(len(lines))}


def main() -> None:
    options = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    options.add_argument("--runs", type=int, default=20)
    runs = options.parse_args().runs
    figures = asyncio.run(measure(runs))
    print(f"rdisc lsp, through a real LSP client over stdio, {figures['lines']:.0f}-line description, "
          f"median of {runs}:")
    print(f"  change re-checked and diagnostics published  {figures['change']:8.1f} ms  "
          f"(target {CHANGE_TARGET_MS:.0f} ms)")
    print(f"{'  a character more at the top, published':47}{figures['moves']:8.1f} ms  "
          f"(target {CHANGE_TARGET_MS:.0f} ms)")
    print(f"{'    the check alone (in process), whole file':47}{figures['check']:8.1f} ms")
    print(f"{'    the same, the changed part only':47}{figures['edited']:8.1f} ms")
    print(f"{'    a character more at the top (the rest moves)':47}{figures['moved']:8.1f} ms  "
          f"(target {CHANGE_TARGET_MS:.0f} ms; what only moved is taken again, its spans moved in place)")
    print(f"  hover on a call of a primitive               {figures['hover']:8.1f} ms  "
          f"(target {ANSWER_TARGET_MS:.0f} ms)")
    print(f"  completion inside a pack list                {figures['completion']:8.1f} ms  "
          f"(target {ANSWER_TARGET_MS:.0f} ms)")


if __name__ == "__main__":
    main()
