#!/usr/bin/env bash
# Installs kerfcam-bindgen (tools/bindgen) into cargo's bin folder unless the right one is there: the web
# build's JS glue, wasm-bindgen's own library (wasm-bindgen-cli-support) at exactly the version of the crate's
# wasm-bindgen in Cargo.lock. scripts/build-wasm.sh runs it, in the background of the wasm's own compilation.
#
# No registry this machine reaches has wasm-bindgen prebuilt, so it is built once per machine, as cheaply as
# it honestly can be (issue 40; CPU time, user+sys, on this 2-core machine):
# - the library alone, without wasm-bindgen-cli's test runner, HTTP client and server: 198 s against the
#   CLI's 465 s (also built without its TLS feature), both at opt-level 1;
# - at opt-level 0: 100 s. The tool then takes 2.5 s instead of 0.6 s on the nester's 3 MB module, same
#   bytes out; the env vars override only this install's release profile.
# The wasm tests run the built www/pkg under Node's own test runner (tests/wasm/), so
# wasm-bindgen-test-runner is not needed either.
#
#   scripts/install-bindgen.sh           install if missing or of another version
#   scripts/install-bindgen.sh --check   exit 0 if the right one is installed, 1 if not (installs nothing)
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="${CARGO_HOME:-$HOME/.cargo}/bin:$PATH"

BINDGEN=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
if [ -z "$BINDGEN" ]; then
  echo "error: no wasm-bindgen in Cargo.lock" >&2
  exit 1
fi
# tools/bindgen pins the version twice: its own (which --version prints and the build stamp keys on) and its
# dependency's. Both must be the crate's.
if ! grep -qx "version = \"$BINDGEN\"" tools/bindgen/Cargo.toml ||
  ! grep -qx "wasm-bindgen-cli-support = \"=$BINDGEN\"" tools/bindgen/Cargo.toml; then
  echo "error: Cargo.lock has wasm-bindgen $BINDGEN: set tools/bindgen/Cargo.toml's version and its" \
    "wasm-bindgen-cli-support pin to it (then cargo update in tools/bindgen)" >&2
  exit 1
fi

if command -v kerfcam-bindgen >/dev/null 2>&1 &&
  [ "$(kerfcam-bindgen --version)" = "kerfcam-bindgen $BINDGEN (wasm-bindgen)" ]; then
  echo "ok: kerfcam-bindgen $BINDGEN present"
  exit 0
fi
if [ "${1:-}" = --check ]; then exit 1; fi

echo "installing kerfcam-bindgen $BINDGEN (tools/bindgen)"
# In cargo install's own temporary folder, not a CARGO_TARGET_DIR the wasm build running beside it locks.
unset CARGO_TARGET_DIR
env CARGO_PROFILE_RELEASE_OPT_LEVEL=0 CARGO_PROFILE_RELEASE_LTO=false CARGO_PROFILE_RELEASE_CODEGEN_UNITS=16 \
  CARGO_PROFILE_RELEASE_DEBUG=false cargo install --path tools/bindgen --locked --force --quiet
echo "installed kerfcam-bindgen $BINDGEN: $(command -v kerfcam-bindgen)"
