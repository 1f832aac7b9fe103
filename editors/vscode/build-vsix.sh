#!/usr/bin/env bash
# Builds editors/vscode/gcnc.vsix: the extension's dependencies from npm (package-lock.json), TypeScript,
# then @vscode/vsce's package (docs/editors.md, "VS Code"). Not part of the test run.
set -eu
cd "$(dirname "$0")"
npm ci --no-audit --no-fund
npm run package
