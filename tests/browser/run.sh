#!/usr/bin/env bash
# ctest entry of the browser test: makes sure Chromium, Node.js and playwright-core are there (through
# the project's script, never by skipping), then runs serve.test.mjs.
#   run.sh <path to the glint binary> <output folder for the screenshot and the saved PNG>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
"$here/../../scripts/install-browser-deps.sh"
exec node "$here/serve.test.mjs" "$@"
