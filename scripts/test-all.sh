#!/usr/bin/env bash
# Every test layer, in order, stopping at the first failure. Run scripts/setup.sh test first (npm test does).
#
# Each layer's wall time is printed after it (issue 40: where the time goes). The native tests build with
# the ci profile (Cargo.toml: release's opt-level 3 without its fat LTO, whose link was most of the layer),
# into one integration-test binary (tests/it/main.rs). The web build is skipped when www/pkg already holds
# a build of the same sources (scripts/build-wasm.sh's stamp), e.g. the one npm start made; the wasm and
# browser layers both test that build.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="$HOME/.cargo/bin:$PATH"

header() { printf '\n==== %s ====\n' "$*"; }
T0=$SECONDS
LAYERS=()
timed() { # NAME COMMAND...: runs it, then prints and keeps its wall time
  local name=$1 t=$SECONDS
  shift
  "$@"
  LAYERS+=("$(printf '%-34s %4d s' "$name" $((SECONDS - t)))")
  printf -- '---- %s: %d s\n' "$name" $((SECONDS - t))
}

header "1/4 native unit and integration tests: cargo test --profile ci"
timed "1/4 native tests" cargo test --profile ci

header "2/4 web build: scripts/build-wasm.sh"
timed "2/4 web build" bash scripts/build-wasm.sh

header "3/4 wasm tests under Node: node --test tests/wasm/"
# The page's own modules (www/pkg, just built or reused) through their JavaScript API, under Node's test
# runner: the wasm is built once per run, as it ships, and tested as the page loads it (issue 40).
timed "3/4 wasm tests" node --test tests/wasm/

header "4/4 browser end-to-end tests: node --test tests/browser/ (one chromium: scripts/browser-tests.mjs)"
timed "4/4 browser tests" node scripts/browser-tests.mjs

header "wall time per layer"
printf '%s\n' "${LAYERS[@]}"
printf '%-34s %4d s\n' "total" $((SECONDS - T0))
