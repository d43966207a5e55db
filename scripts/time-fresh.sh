#!/usr/bin/env bash
# Times what a newcomer waits for (issue 40) on a clean clone of this repository's committed HEAD in a
# temporary directory: `npm start` until the page's first byte is served, `npm start` again with nothing
# changed, then `npm test` (whose last lines are scripts/test-all.sh's wall time per layer). Prints the
# figures; it asserts none (a figure in the log, not a timed test). Every line of npm's output is kept,
# prefixed with the seconds since its command started, so the log shows where the time went.
#
#   bash scripts/time-fresh.sh [--fresh-home] [--no-test]
#
# What it resets, as on a fresh machine: the checkout (git clone of HEAD: no target/, no www/pkg, no
# node_modules, no build stamp; npm ci installs node_modules).
#
# With --fresh-home it also hides this machine's per-user state: HOME, CARGO_HOME and the npm cache point
# into the temporary directory, so scripts/build-wasm.sh builds kerfcam-bindgen (tools/bindgen) from source
# (`cargo install`, into the fresh CARGO_HOME's bin, which setup.sh puts on PATH), cargo downloads every
# crate and npm every package afresh (network needed). ~/.cargo/bin leaves PATH; cargo, rustc and rustup
# are reached through links to the rustup proxy in a directory of their own.
#
# What it cannot reset, even with --fresh-home: the Rust toolchain and its wasm32 target (RUSTUP_HOME:
# rustup downloads them; setup.sh only asks for the target), the Debian packages (nodejs, chromium,
# firefox-esr, linuxcnc-uspace: setup.sh installs them with apt when missing, which a fresh machine pays
# once), the page cache of the files read, and the load other processes put on the machine. Without
# --fresh-home, also the cargo registry cache (~/.cargo/registry), the npm cache (~/.npm) and the
# kerfcam-bindgen binary in ~/.cargo/bin.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
SRC=$PWD
RUN_TESTS=1
FRESH_HOME=0
for arg in "$@"; do
  case "$arg" in
    --no-test) RUN_TESTS=0 ;;
    --fresh-home) FRESH_HOME=1 ;;
    *)
      echo "usage: $0 [--fresh-home] [--no-test]" >&2
      exit 2
      ;;
  esac
done
REV=$(git rev-parse HEAD)
if [ -n "$(git status --porcelain --untracked-files=no)" ]; then
  echo "note: uncommitted changes are not timed: the clone is of HEAD $REV"
fi

DIR=$(mktemp -d "${TMPDIR:-/tmp}/kerfcam-fresh-XXXXXX")
SERVER=
cleanup() {
  if [ -n "$SERVER" ]; then kill -- "-$SERVER" 2>/dev/null || true; fi
  rm -rf "$DIR"
}
trap cleanup EXIT

# Beside a link to the shared material, so ../shared (corpus, fixtures) resolves as in the real checkout.
git clone -q --no-checkout "$SRC" "$DIR/kerfcam"
git -C "$DIR/kerfcam" checkout -q "$REV"
if [ -d "$SRC/../shared" ]; then ln -s "$(cd "$SRC/../shared" && pwd)" "$DIR/shared"; fi
cd "$DIR/kerfcam"
echo "clone of $REV in $DIR/kerfcam"

if [ "$FRESH_HOME" = 1 ]; then
  real_cargo_home=${CARGO_HOME:-$HOME/.cargo}
  export RUSTUP_HOME=${RUSTUP_HOME:-$HOME/.rustup}
  export HOME=$DIR/home
  export CARGO_HOME=$HOME/.cargo
  export npm_config_cache=$HOME/.npm
  mkdir -p "$CARGO_HOME/bin" "$DIR/rust-bin"
  for tool in cargo rustc rustup rustdoc cargo-clippy clippy-driver cargo-fmt rustfmt; do
    if [ -e "$real_cargo_home/bin/$tool" ]; then ln -s "$real_cargo_home/bin/$tool" "$DIR/rust-bin/$tool"; fi
  done
  path=$DIR/rust-bin
  IFS=: read -ra dirs <<<"$PATH"
  for d in "${dirs[@]}"; do
    if [ "$d" != "$real_cargo_home/bin" ]; then path+=:$d; fi
  done
  export PATH=$path
  for tool in kerfcam-bindgen wasm-bindgen wasm-bindgen-test-runner; do
    if command -v "$tool" >/dev/null; then echo "note: $tool still on PATH: $(command -v "$tool")"; fi
  done
  echo "fresh HOME $HOME (CARGO_HOME $CARGO_HOME, npm cache $npm_config_cache; RUSTUP_HOME $RUSTUP_HOME kept)"
fi

# A port nothing answers on yet, so the first byte timed is this server's.
PORT=${PORT:-$((20000 + RANDOM % 20000))}
if curl -s -o /dev/null "http://127.0.0.1:$PORT/"; then
  echo "error: something already answers on port $PORT; set PORT" >&2
  exit 1
fi

stamp() { # prefixes each line with the seconds since $1
  local t0=$1 line
  while IFS= read -r line; do printf '[%4d s] %s\n' $((SECONDS - t0)) "$line"; done
}

first_byte() { # NAME: runs npm start until the page's first byte, prints its log, keeps the seconds in $took
  local name=$1 t0=$SECONDS log=$DIR/$1.log
  # setsid: npm, its shell and the server in a group of their own, stopped together below.
  setsid npm start > >(stamp "$t0" >"$log") 2>&1 &
  SERVER=$!
  until curl -s -o /dev/null "http://127.0.0.1:$PORT/"; do
    if ! kill -0 "$SERVER" 2>/dev/null; then
      cat "$log"
      echo "error: npm start ended before serving" >&2
      exit 1
    fi
    sleep 0.5
  done
  took=$((SECONDS - t0))
  # The nester module (Sheet mode) follows the page (build-wasm.sh --serve): the server holds its wasm until
  # it is built, so this request ends when Sheet mode could first nest.
  if ! curl -s -f -o /dev/null --max-time 1800 "http://127.0.0.1:$PORT/pkg/kerfcam_nest_bg.wasm"; then
    cat "$log"
    echo "error: npm start served no nester module" >&2
    exit 1
  fi
  nester=$((SECONDS - t0))
  kill -- "-$SERVER" 2>/dev/null || true
  wait "$SERVER" 2>/dev/null || true
  SERVER=
  sleep 0.2 # the log's reader drains
  printf '\n==== %s: npm start ====\n' "$name"
  cat "$log"
}

export PORT
# Each figure is printed as soon as it is measured (a run stopped halfway keeps what it had), then all
# three together at the end.
first_byte fresh
fresh=$took
fresh_nester=$nester
echo "---- npm start, clean clone, to the first byte: $fresh s (the nester module, Sheet mode: $fresh_nester s)"
first_byte again
again=$took
echo "---- npm start again, nothing changed: $again s"

tested=
if [ "$RUN_TESTS" = 1 ]; then
  printf '\n==== npm test ====\n'
  t0=$SECONDS
  if npm test 2>&1 | stamp "$t0"; then result=passed; else result=FAILED; fi
  tested="$((SECONDS - t0)) s ($result)"
  echo "---- npm test: $tested"
fi

printf '\n==== times (clone of %s) ====\n' "$REV"
echo "npm start, clean clone, to the first byte: $fresh s"
echo "  ... to the nester module (Sheet mode):      $fresh_nester s"
echo "npm start again, nothing changed:          $again s"
if [ -n "$tested" ]; then echo "npm test after them:                        $tested"; fi
