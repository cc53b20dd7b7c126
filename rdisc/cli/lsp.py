"""`rdisc lsp`: the language server, over stdin and stdout, for an editor to start once and keep
(diagnostics as you type, quick fixes, hover with a primitive's bytes, go to definition, rename,
completion, outline). pygls is imported here, when the verb runs: `rdisc check` never loads it."""

from __future__ import annotations

import argparse

from rdisc.cli.output import EXIT_OK


def add_parser(verbs: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    p = verbs.add_parser("lsp", help="run the language server over stdio (for an editor to start)",
                         description="Serve the Language Server Protocol on stdin and stdout until the editor "
                                     "asks it to exit: start it from an editor, not by hand.")
    # vscode-languageclient adds `--stdio` to the command of a server it starts over stdio, as the
    # servers it starts expect (editors/vscode's extension is one); stdio is the only transport here.
    p.add_argument("--stdio", action="store_true", help="serve on stdin and stdout (what it does anyway)")
    p.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    from rdisc.editor.server import serve

    serve()
    return EXIT_OK
