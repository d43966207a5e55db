#!/usr/bin/env bash
# Installs node_modules (npm ci) unless every package the build and the tests use is there.
#
#   scripts/install-node-modules.sh           install when something is missing
#   scripts/install-node-modules.sh --check   exit 0 when nothing is missing, 1 otherwise
#
# The packages: binaryen (a current wasm-opt for the build; Debian 12's is too old), fflate (the page's zip),
# playwright-core and puppeteer-core (tests; puppeteer-core never downloads a browser, and
# PUPPETEER_SKIP_DOWNLOAD says so twice) and axe-core (the accessibility test). scripts/setup.sh test runs it;
# scripts/build-wasm.sh runs it beside the wasm's cargo builds, which need none of it (issue 40: a fresh
# machine's npm start).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."

present() {
  [ -x node_modules/.bin/wasm-opt ] && [ -f node_modules/playwright-core/package.json ] &&
    [ -f node_modules/puppeteer-core/package.json ] && [ -f node_modules/fflate/package.json ] &&
    [ -f node_modules/axe-core/package.json ]
}

if [ "${1:-}" = --check ]; then
  present
  exit
fi
if present; then
  echo "ok: node_modules present (binaryen, playwright-core, puppeteer-core, fflate, axe-core)"
else
  echo "installing node_modules (npm ci)"
  export PUPPETEER_SKIP_DOWNLOAD=1
  npm ci --no-audit --no-fund
fi
