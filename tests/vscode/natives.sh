#!/bin/sh
# What code-server's own postinstall does (`npm ci` installs it with --ignore-scripts), less what
# the tests never use and cannot have offline: kerberos (a proxy's Negotiate authentication; it
# needs libkrb5's headers), ripgrep (searching files; its binary comes from GitHub), node-pty (the
# terminal) and the built-in extensions' TypeScript. Native modules are compiled against the
# headers of the node that runs them, found beside it when they are there (node-gyp downloads them
# from nodejs.org otherwise).
set -eu
cd "$(dirname "$0")"
headers="$(dirname "$(dirname "$(command -v node)")")"
if [ -z "${npm_config_nodedir:-}" ] && [ -f "$headers/include/node/common.gypi" ]; then
    export npm_config_nodedir="$headers"
fi
npm rebuild argon2                      # code-server reads it at start, though --auth none never hashes
cd node_modules/code-server/lib/vscode
npm install --omit=dev --ignore-scripts --no-audit --no-fund  # as code-server's postinstall does
npm rebuild @vscode/spdlog @vscode/deviceid native-watchdog
ln -sfn node_modules node_modules.asar  # where VS Code and its built-in extensions look for modules
