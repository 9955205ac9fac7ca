#!/usr/bin/env bash
# Installs what the browser test of `glint serve` needs and nothing else: Debian's Chromium and Node.js
# (for playwright-core, which drives the installed Chromium; no browser is downloaded from the web),
# then the npm packages pinned in tests/browser/package-lock.json.
# Idempotent: apt-get runs only when something is missing, npm only when node_modules is missing.
set -euo pipefail

missing=()
dpkg-query -W -f='${Status}' chromium 2>/dev/null | grep -q 'install ok installed' || missing+=(chromium)
# Node.js may come from elsewhere than Debian (e.g. NodeSource): a working node and npm are enough.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  missing+=(nodejs npm)
fi
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then
    sudo="sudo"
  fi
  echo "install-browser-deps: installing ${missing[*]}" >&2
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi

browser_dir="$(cd "$(dirname "$0")/../tests/browser" && pwd)"
if [ ! -d "$browser_dir/node_modules/playwright-core" ]; then
  echo "install-browser-deps: npm ci in $browser_dir" >&2
  (cd "$browser_dir" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error)
fi
