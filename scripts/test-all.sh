#!/usr/bin/env bash
# Every test layer, in order, stopping at the first failure. Run scripts/setup.sh test first (npm test does).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="$HOME/.cargo/bin:$PATH"

header() { printf '\n==== %s ====\n' "$*"; }

header "1/4 native unit and integration tests: cargo test --release"
cargo test --release

header "2/4 wasm tests under Node: wasm-pack test --node --release"
# As it ships: the wasm at opt-level "s" (scripts/build-wasm.sh).
CARGO_PROFILE_RELEASE_OPT_LEVEL=s wasm-pack test --node --release

header "3/4 web build: scripts/build-wasm.sh"
bash scripts/build-wasm.sh

header "4/4 browser end-to-end tests: node --test tests/browser/"
node --test tests/browser/
