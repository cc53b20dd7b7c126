// Runs editors/vscode/extension.js against stand-ins for the `vscode` API and
// vscode-languageclient, and prints as JSON what it did: the language clients it made (their
// server command, arguments, transport and documents), their starts and stops, its error
// messages. Usage: node extension_check.js EXTENSION.js
"use strict";
const Module = require("module");

const events = [];
let settings = {};
let failStart = false;
let changeListener = null;

const vscode = {
  workspace: {
    getConfiguration: (section) => ({
      get: (key, fallback) => (section + "." + key in settings ? settings[section + "." + key] : fallback),
    }),
    onDidChangeConfiguration: (listener) => {
      changeListener = listener;
      return { dispose() {} };
    },
  },
  window: { showErrorMessage: (message) => events.push(["error", message]) },
};

class LanguageClient {
  constructor(id, name, server, client) {
    this.id = id;
    events.push(["client", id, name, server, client.documentSelector]);
  }
  async start() {
    events.push(["start", this.id]);
    if (failStart) throw new Error("spawn rdisc ENOENT");
  }
  async stop() {
    events.push(["stop", this.id]);
  }
}
const languageclient = { LanguageClient, TransportKind: { stdio: 0, ipc: 1, pipe: 2, socket: 3 } };

const load = Module._load;
Module._load = function (request, parent, isMain) {
  if (request === "vscode") return vscode;
  if (request === "vscode-languageclient/node") return languageclient;
  return load.call(this, request, parent, isMain);
};

async function main() {
  const extension = require(require("path").resolve(process.argv[2]));
  const context = { subscriptions: [] };
  events.push(["step", "activate with no settings"]);
  await extension.activate(context);
  events.push(["step", "an unrelated setting changes"]);
  await changeListener({ affectsConfiguration: (section) => section === "editor" });
  events.push(["step", "rdis.server.path changes"]);
  settings = { "rdis.server.path": "/opt/robots/.venv/bin/rdisc" };
  await changeListener({ affectsConfiguration: (section) => section === "rdis.server" || section === "rdis" });
  events.push(["step", "the server cannot start"]);
  settings = { "rdis.server.path": "rdisc-missing", "rdis.server.args": ["lsp", "--verbose"] };
  failStart = true;
  await changeListener({ affectsConfiguration: (section) => section === "rdis.server" || section === "rdis" });
  events.push(["step", "deactivate"]);
  await extension.deactivate();
  process.stdout.write(JSON.stringify({ subscriptions: context.subscriptions.length, events }));
}

main().catch((error) => {
  process.stderr.write(String(error && error.stack ? error.stack : error) + "\n");
  process.exit(1);
});
