#!/usr/bin/env bash
# Installs what kerfcam needs, skipping whatever is already present.
#
#   scripts/setup.sh build     Rust wasm32 target, node and npm (node_modules: scripts/build-wasm.sh installs it)
#   scripts/setup.sh node      the same and node_modules
#   scripts/setup.sh packages  only Debian's chromium, firefox-esr and linuxcnc-uspace (rs274)
#   scripts/setup.sh test      node, then packages
#
# npm test runs `node` first and `packages` beside the native build (scripts/test-all.sh --packages): apt
# waits on the network and the disk, the build on the CPU.
#
# The web build's JS glue tool, kerfcam-bindgen, is installed by scripts/build-wasm.sh when it first needs it,
# beside the wasm's own compilation (scripts/install-bindgen.sh).
# No tool is allowed to download its own binaries here: scripts/build-wasm.sh runs kerfcam-bindgen and wasm-opt
# itself (no wasm-pack), playwright-core drives Debian's chromium and puppeteer-core Debian's firefox-esr.
set -euo pipefail

MODE=${1:-}
case "$MODE" in
  build | node | packages | test) ;;
  *)
    echo "usage: $0 build|node|packages|test" >&2
    exit 2
    ;;
esac

cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="$HOME/.cargo/bin:$PATH"
export DEBIAN_FRONTEND=noninteractive

have() { command -v "$1" >/dev/null 2>&1; }
ok() { echo "ok: $1 present"; }
installing() { echo "installing $1"; }

SUDO=()
if [ "$(id -u)" -ne 0 ] && have sudo; then SUDO=(sudo -E); fi

APT_UPDATED=0
apt_install() {
  if [ "$APT_UPDATED" -eq 0 ]; then
    "${SUDO[@]}" apt-get update -qq
    APT_UPDATED=1
  fi
  "${SUDO[@]}" apt-get install -y -qq "$@"
}

# --- build -------------------------------------------------------------------------------------------

if [ "$MODE" != packages ]; then
if ! have cargo || ! have rustup; then
  echo "error: cargo and rustup are needed (https://rustup.rs); install them first" >&2
  exit 1
fi

if rustup target list --installed | grep -qx wasm32-unknown-unknown; then
  ok "rust target wasm32-unknown-unknown"
else
  installing "rust target wasm32-unknown-unknown"
  rustup target add wasm32-unknown-unknown
fi

# node_modules (scripts/install-node-modules.sh says what is in it): for a build, scripts/build-wasm.sh installs
# it beside the wasm's cargo builds, which do not need it; the tests need it first.
if ! have node || ! have npm; then
  installing "nodejs npm"
  apt_install nodejs npm
fi
if [ "$MODE" != build ]; then
  bash scripts/install-node-modules.sh
elif bash scripts/install-node-modules.sh --check; then
  ok "node_modules"
else
  echo "node_modules: scripts/build-wasm.sh installs it beside the wasm's compilation"
fi
fi

# --- test --------------------------------------------------------------------------------------------

# One apt-get for whatever is missing, without the recommended packages: linuxcnc-uspace recommends a
# real-time kernel, Qt, OpenCV and speech synthesis (463 packages with them on a fresh machine of this
# kind, 119 without, counted with `apt-get -s`; rs274 needs none of them). fonts-liberation is what
# chromium recommends for its text; named so that the page renders with the same fonts either way.
if [ "$MODE" = test ] || [ "$MODE" = packages ]; then
  MISSING=()
  if have chromium; then
    ok "chromium ($(chromium --version 2>/dev/null | head -n 1))"
  else
    MISSING+=(chromium fonts-liberation)
  fi
  # The single-file build is tested in Firefox too (tests/browser/single-file.test.mjs).
  if have firefox-esr; then
    ok "firefox-esr ($(firefox-esr --version 2>/dev/null | head -n 1))"
  else
    MISSING+=(firefox-esr)
  fi
  if have rs274; then
    ok "linuxcnc-uspace (rs274)"
  else
    MISSING+=(linuxcnc-uspace)
  fi
  if [ ${#MISSING[@]} -gt 0 ]; then
    installing "${MISSING[*]}"
    apt_install --no-install-recommends "${MISSING[@]}"
  fi
fi
