#!/usr/bin/env bash
# Browser test of the built book: installs what a fresh machine lacks (Chromium from Debian's
# packages, playwright-core from npm), then runs check.mjs.
#
# Usage: bash tools/browser/run.sh [BOOK_DIR [SCREENSHOT_DIR]]
#   BOOK_DIR defaults to the repository's book/ (build it first: `cargo run --release -- book`);
#   a relative path is taken from the directory the script is called from.
#   SCREENSHOT_DIR defaults to /tmp/raylemma-browser.
# Environment: CHROMIUM (default /usr/bin/chromium), SEARCH_TERMS (default Fresnel,Schlick).
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
root="$(cd "$here/../.." && pwd)"

abs() { case "$1" in /*) printf '%s\n' "$1" ;; *) printf '%s/%s\n' "$PWD" "$1" ;; esac; }
book="$(abs "${1:-$root/book}")"
shots="$(abs "${2:-/tmp/raylemma-browser}")"

export DEBIAN_FRONTEND=noninteractive
chromium="${CHROMIUM:-/usr/bin/chromium}"
if [ ! -x "$chromium" ]; then
    echo "run.sh: $chromium missing: installing Debian's chromium"
    apt-get update -q
    apt-get install -y -q chromium </dev/null
fi
"$chromium" --version 2>/dev/null | grep -v '^\s*$' || true

if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
    echo "run.sh: node and npm are needed (Node 20 or later)" >&2
    exit 2
fi
if [ ! -d "$here/node_modules/playwright-core" ]; then
    echo "run.sh: installing playwright-core (npm ci)"
    # No browser download: playwright-core has none, and Chromium is Debian's.
    (cd "$here" && PLAYWRIGHT_SKIP_BROWSER_DOWNLOAD=1 npm ci --no-audit --no-fund --loglevel=error </dev/null)
fi
echo "node $(node --version), playwright-core $(node -p "require('$here/node_modules/playwright-core/package.json').version")"

exec node "$here/check.mjs" "$book" "$shots"
