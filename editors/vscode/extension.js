// Starts `rdisc lsp` (the setting rdis.server.path, default `rdisc`, with rdis.server.args,
// default ["lsp"]) over stdio for .rdis files, and restarts it when those settings change.
// Colours come from syntaxes/rdis.tmLanguage.json without any server.
"use strict";
const vscode = require("vscode");
const { LanguageClient, TransportKind } = require("vscode-languageclient/node");

let client;

function serverOptions() {
  const settings = vscode.workspace.getConfiguration("rdis");
  const command = settings.get("server.path", "rdisc") || "rdisc";
  const args = settings.get("server.args", ["lsp"]);
  return { command, args, transport: TransportKind.stdio };
}

async function start() {
  const server = serverOptions();
  client = new LanguageClient("rdis", "RDIS language server", server, {
    documentSelector: [{ scheme: "file", language: "rdis" }, { scheme: "untitled", language: "rdis" }],
  });
  try {
    await client.start();
  } catch (error) {
    client = undefined;
    vscode.window.showErrorMessage(
      `RDIS: could not start \`${[server.command, ...server.args].join(" ")}\` (${error && error.message ? error.message : error}). ` +
        "Install rdisc (pip install rdisc) or set rdis.server.path to its command.");
  }
}

async function stop() {
  if (client) {
    const running = client;
    client = undefined;
    await running.stop();
  }
}

async function activate(context) {
  context.subscriptions.push(
    vscode.workspace.onDidChangeConfiguration(async (event) => {
      if (event.affectsConfiguration("rdis.server")) {
        await stop();
        await start();
      }
    }),
  );
  await start();
}

function deactivate() {
  return stop();
}

module.exports = { activate, deactivate };
