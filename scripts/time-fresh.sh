#!/usr/bin/env bash
# Times what a newcomer waits for (issue 40), on a clean clone of this repository's HEAD in a temporary
# directory: `npm start` until the page's first byte is served, `npm start` again with nothing changed,
# then `npm test`. Prints the three figures (a figure in the log, not an assertion). The clone has no
# target/ and no www/pkg; node_modules is installed by npm ci as on a fresh machine unless KEEP_NODE_MODULES=1
# links this checkout's.
#
#   bash scripts/time-fresh.sh [--no-test]
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
SRC=$PWD
RUN_TESTS=1
[ "${1:-}" = --no-test ] && RUN_TESTS=0
DIR=$(mktemp -d "${TMPDIR:-/tmp}/kerfcam-fresh-XXXXXX")
trap 'rm -rf "$DIR"' EXIT
# Beside a checkout of the same parent, so ../shared (fixtures, corpus) resolves as in the real one.
git clone -q "$SRC" "$DIR/kerfcam"
ln -s "$(cd "$SRC/.." && pwd)/shared" "$DIR/shared"
cd "$DIR/kerfcam"
if [ "${KEEP_NODE_MODULES:-0}" = 1 ]; then ln -s "$SRC/node_modules" node_modules; fi
PORT=${PORT:-18080}

first_byte() { # seconds from `npm start` to the page's first byte
  local t0=$SECONDS pid
  PORT=$PORT npm start >"$DIR/start.log" 2>&1 &
  pid=$!
  until curl -sf -o /dev/null "http://127.0.0.1:$PORT/"; do
    if ! kill -0 "$pid" 2>/dev/null; then
      cat "$DIR/start.log" >&2
      echo "npm start ended before serving" >&2
      exit 1
    fi
    sleep 0.5
  done
  echo $((SECONDS - t0))
  kill -- "-$pid" 2>/dev/null || kill "$pid"
  wait "$pid" 2>/dev/null || true
}

set -m # npm start in its own process group, so the server under it is stopped with it
fresh=$(first_byte)
again=$(first_byte)
set +m
echo "npm start, clean clone, to the first byte: $fresh s"
echo "npm start again, nothing changed:          $again s"
if [ "$RUN_TESTS" = 1 ]; then
  t0=$SECONDS
  npm test
  echo "npm test after it:                         $((SECONDS - t0)) s"
fi
