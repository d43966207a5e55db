#!/usr/bin/env bash
# Every test layer. Run scripts/setup.sh test first (npm test does).
#
# Two chains run side by side (issue 40), each printing its lines live with its name in front:
#   native: the native build (`cargo test --profile ci --no-run`), then the unit and integration tests;
#   web:    the web build (scripts/build-wasm.sh: skipped when www/pkg already holds a build of the same
#           sources, e.g. npm start's), then the wasm tests under Node, then, once the native build is
#           done, the browser tests (beside the native tests).
# Alone, the browser layer kept about one of this machine's two cores busy (288 s of CPU in 365 s of wall
# time): the native chain fills the other. A chain stops at its first failing layer; the other goes on,
# so one run shows every failure. Each layer's wall time and CPU time are printed after it, and all of them at the end.
# KERFCAM_TEST_SERIAL=1 runs the chains one after the other (each layer's time alone).
#
# --packages (npm test): a third chain installs the Debian packages the tests run (scripts/setup.sh
# packages: chromium, firefox-esr, rs274) beside the builds, which do not need them; the native tests and
# the browser tests wait for it. On a fresh machine apt-get took 181 s before the tests (issue 40), mostly
# waiting on the network and the disk while the native build waits on the CPU.
#
# The native tests build with the ci profile (Cargo.toml: release's opt-level 3 without its fat LTO,
# whose link was most of the layer), into one integration-test binary (tests/it/main.rs). The web chain's
# cargo builds into target/wasm32-unknown-unknown and target/serve, the native one into target/ci: cargo
# locks each profile's directory, so the two do not wait for each other.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="$HOME/.cargo/bin:$PATH"

PACKAGES=0
for arg in "$@"; do
  case "$arg" in
    --packages) PACKAGES=1 ;;
    *)
      echo "usage: $0 [--packages]" >&2
      exit 2
      ;;
  esac
done

T0=$SECONDS
TIMES=$(mktemp)
# Every chain's lines, for the list of failed tests printed last: CI shows only the end of the output.
OUTPUT=$(mktemp)

# The CPU seconds (user + system) of this shell's finished children so far, from bash's `times`, into
# the variable CPU (`times` in a command substitution would be the subshell's own, none).
CPU_FILE=$(mktemp)
children_cpu() {
  times >"$CPU_FILE"
  CPU=$(tail -1 "$CPU_FILE" | awk '{ s = 0; for (i = 1; i <= 2; i++) { split($i, t, /[ms]/); s += t[1] * 60 + t[2] } printf "%.2f", s }')
}

# layer NAME COMMAND...: runs it, prints and records its wall time, its CPU time and exit status. The CPU
# time (every process it started, user + system) does not depend on what else the machine runs, as the
# wall time does: the figure to compare between runs on a shared machine.
layer() {
  local name=$1 t=$SECONDS c rc=0 CPU
  children_cpu
  c=$CPU
  shift
  printf '\n==== %s: %s ====\n' "$name" "$*"
  "$@" || rc=$?
  children_cpu
  local wall=$((SECONDS - t)) cpu
  cpu=$(awk -v a="$c" -v b="$CPU" 'BEGIN { printf "%.0f", b - a }')
  printf -- '---- %s: %d s, %d s of CPU%s\n' "$name" $wall $cpu "$([ $rc -eq 0 ] || echo ", FAILED ($rc)")"
  printf '%-32s %4d s  %5d s of CPU%s\n' "$name" $wall $cpu "$([ $rc -eq 0 ] || echo '  FAILED')" >>"$TIMES"
  return $rc
}

# The browser tests that compare the page's program with the command line's (milling.test.mjs) wait for
# this file: "ok" once the native chain has built target/ci/kerfcam, "failed" if it could not.
READY=$(mktemp -u)
export KERFCAM_BIN_READY=$READY
# "ok" once the Debian packages are there, "failed" if they could not be installed.
PACKAGES_READY=$(mktemp -u)
trap 'rm -f "$TIMES" "$OUTPUT" "$READY" "$PACKAGES_READY" "$CPU_FILE"' EXIT

packages() {
  if layer "Debian packages" bash scripts/setup.sh packages; then
    echo ok >"$PACKAGES_READY"
  else
    echo failed >"$PACKAGES_READY"
    return 1
  fi
}
if [ "$PACKAGES" = 0 ]; then echo ok >"$PACKAGES_READY"; fi

# wait_for FILE: waits until FILE says how its layer ended; true if "ok".
wait_for() {
  while [ ! -s "$1" ]; do sleep 1; done
  [ "$(cat "$1")" = ok ]
}

native() {
  if layer "native build" cargo test --profile ci --no-run; then
    echo ok >"$READY"
  else
    echo failed >"$READY"
    return 1
  fi
  if [ "$PACKAGES" = 1 ]; then layer "waiting for the Debian packages" wait_for "$PACKAGES_READY"; fi &&
    layer "native tests" cargo test --profile ci
}

web() {
  # The wasm tests: the page's own modules (www/pkg, just built or reused) through their JavaScript API,
  # under Node's test runner. The browser tests: scripts/browser-tests.mjs, one chromium.
  layer "web build" bash scripts/build-wasm.sh &&
    layer "wasm tests" node --test tests/wasm/ &&
    layer "waiting for the native build" wait_for "$READY" &&
    { [ "$PACKAGES" = 0 ] || layer "waiting for the Debian packages" wait_for "$PACKAGES_READY"; } &&
    layer "browser tests" node scripts/browser-tests.mjs
}

# The browser layer starts once the native build is done: beside it, the build's long single-threaded
# steps (the library and its test harness, each one rustc) got a share of a core and stretched from 223 s
# alone to 714 s (a fresh clone of b0b03a8), more than the overlap saved. Beside the native tests, which
# keep both cores busy, the two only share the CPU.

# run NAME FUNCTION: the chain's lines with its name in front, live; its status returned.
run() {
  local name=$1
  set +e
  (set -o pipefail; "$2" 2>&1 | sed -u "s/^/[$name] /" | tee -a "$OUTPUT")
  local rc=$?
  set -e
  return $rc
}

rc_native=0 rc_web=0 rc_packages=0
if [ "${KERFCAM_TEST_SERIAL:-0}" = 1 ]; then
  if [ "$PACKAGES" = 1 ]; then run packages packages || rc_packages=$?; fi
  run native native || rc_native=$?
  run web web || rc_web=$?
else
  if [ "$PACKAGES" = 1 ]; then
    run packages packages &
    pid_packages=$!
  fi
  run native native &
  pid_native=$!
  run web web &
  pid_web=$!
  wait $pid_native || rc_native=$?
  wait $pid_web || rc_web=$?
  if [ "$PACKAGES" = 1 ]; then wait $pid_packages || rc_packages=$?; fi
fi

# failed_tests: each failed test's name, where and why, in a few lines: the cargo tests' `... FAILED` lines and
# their panics' first line, node's `not ok` lines with their location and error (its YAML block).
failed_tests() {
  printf '\n==== failed tests ====\n'
  awk '
    / \.\.\. FAILED$/ { print; next }
    /panicked at / { print; getline; print; next }
    /^\[[a-z]+\] *not ok / { print; yaml = 1; error = 0; next }
    yaml && /^\[[a-z]+\] *\.\.\.$/ { yaml = 0; next }
    yaml && /  location:/ { print; next }
    yaml && /  error:/ { print; error = /\|-$/ ? 2 : 0; next }
    yaml && error > 0 { if ($0 !~ /^\[[a-z]+\] *$/) print; error--; next }
  ' "$OUTPUT" | head -16
}

printf '\n==== wall time and CPU time per layer (the two chains side by side) ====\n'
cat "$TIMES"
printf '%-32s %4d s\n' "total" $((SECONDS - T0))
if [ $rc_native -ne 0 ] || [ $rc_web -ne 0 ] || [ $rc_packages -ne 0 ]; then
  failed_tests
  echo "FAILED: native chain $rc_native, web chain $rc_web, packages $rc_packages" >&2
  exit 1
fi
