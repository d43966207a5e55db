#!/usr/bin/env bash
# Builds the release wasm modules and their JS glue into www/pkg (kerfcam.js + kerfcam_bg.wasm, the cutting
# core; kerfcam_nest.js + kerfcam_nest_bg.wasm, the nester) and prints their sizes.
#
#   scripts/build-wasm.sh          for the tests (npm test): one wasm-opt -O1 pass
#   scripts/build-wasm.sh --dist   for shipping (npm run build): wasm-opt -Os --converge, the smallest modules
#   scripts/build-wasm.sh --serve  npm start: as the first, serving www/ (scripts/serve.mjs) as soon as the cutting
#                                  core is built, the nester module following
#
# Skipped when www/pkg already holds a build of the same sources (src/, Cargo.toml, Cargo.lock,
# .cargo/config.toml, this script) with the same tools: the stamp www/pkg/.build-stamp holds their hash.
# A --dist build serves as well, so npm start after npm run build rebuilds nothing. FORCE=1 rebuilds.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="${CARGO_HOME:-$HOME/.cargo}/bin:$PATH"

DIST=0
SERVE=0
case "${1:-}" in
  --dist) DIST=1 ;;
  --serve) SERVE=1 ;;
  "") ;;
  *)
    echo "usage: $0 [--dist | --serve]" >&2
    exit 2
    ;;
esac
T0=$SECONDS
PENDING=www/pkg/.nester-pending
FAILED=www/pkg/.nester-failed
rm -f "$FAILED"

# The page's one third-party module, fflate (MIT; zips the batch's programs), copied from node_modules so
# the page loads it from its own origin (no CDN) and the service worker can keep it offline.
copy_vendor() {
  mkdir -p www/vendor
  cp node_modules/fflate/esm/browser.js www/vendor/fflate.js
  echo "www/vendor/fflate.js: fflate $(node -p "require('./node_modules/fflate/package.json').version")"
}

# --serve (npm start): scripts/serve.mjs in the background once the page can load, waited for at the end.
SERVER_PID=
serve_now() {
  node scripts/serve.mjs &
  SERVER_PID=$!
}

# node_modules (binaryen's wasm-opt, fflate) is needed only after the cargo builds: where it is missing (a fresh
# machine), npm ci runs beside them (scripts/install-node-modules.sh).
node_install=
if ! bash scripts/install-node-modules.sh --check; then
  (set -o pipefail; bash scripts/install-node-modules.sh 2>&1 | sed -u 's/^/[npm ci] /') &
  node_install=$!
fi

# The npm package binaryen comes first: Debian 12's binaryen 108 writes wasm-bindgen's externref table in an
# outdated encoding that browsers refuse ("WebAssembly.Table.set(): Argument 1 is invalid for table"), so a
# system wasm-opt older than 116 is skipped.
export PATH="$PWD/node_modules/.bin:$PATH"
opt=()
version=
find_wasm_opt() { # sets version and opt
  version=$(wasm-opt --version 2>/dev/null | grep -oE '[0-9]+' | head -n 1 || true)
  if [ -z "$version" ]; then
    echo "note: no wasm-opt on PATH; building without it"
    opt=(--no-opt)
  elif [ "$version" -lt 116 ]; then
    echo "note: wasm-opt $version is too old (needs binaryen >= 116); building without it"
    opt=(--no-opt)
  else
    opt=()
    echo "wasm-opt: $(command -v wasm-opt) (binaryen $version)"
  fi
}
if [ -z "$node_install" ]; then find_wasm_opt; fi

# The wasm modules are built for size (opt-level "s"; Cargo.toml's release profile is 3, for the native CLI),
# but for the nester's own crate (below).
# Served (npm start, npm test): Cargo.toml's profile serve, without the fat LTO and single codegen unit
# (the nester's crate build on this quiet 2-core machine, one after the other: 48 s against release's 70 s,
# for a module 3 % larger after wasm-opt). Shipped (--dist): release.
export CARGO_PROFILE_RELEASE_OPT_LEVEL=s
PROFILE=serve
if [ "$DIST" -eq 1 ]; then PROFILE=release; fi

# Two modules from the one crate (issue 17): the cutting core (kerfcam, without the feature "nester"),
# which the page loads at once, and the same pipeline with the nesting engine (kerfcam_nest), which the
# worker loads only when Sheet mode first needs the nester.
#
# The stamp: every input of the build and the tools' versions, and whether the modules were converged.
sources() {
  find src Cargo.toml Cargo.lock .cargo/config.toml scripts/build-wasm.sh tools/bindgen/Cargo.toml -type f \
    2>/dev/null | LC_ALL=C sort | xargs sha256sum
  rustc -V
  echo "wasm-opt ${version:-none}"
}
key=$(sources | sha256sum | cut -d' ' -f1)
STAMP=www/pkg/.build-stamp
outputs=(www/pkg/kerfcam.js www/pkg/kerfcam_bg.wasm www/pkg/kerfcam_nest.js www/pkg/kerfcam_nest_bg.wasm)
built() { # the stamp's key matches and every output is there (never while node_modules is being installed)
  [ -z "$node_install" ] && [ -f "$STAMP" ] || return 1
  for f in "${outputs[@]}"; do [ -f "$f" ] || return 1; done
  local have_key have_dist
  read -r have_key have_dist <"$STAMP" || return 1
  [ "$have_key" = "$key" ] && { [ "$DIST" -eq 0 ] || [ "$have_dist" = dist ]; }
}

if [ "${FORCE:-0}" != 1 ] && built; then
  echo "www/pkg is up to date ($(cut -d' ' -f2 "$STAMP") build of these sources): nothing to build"
  rm -f "$PENDING" # left by a build that was stopped, whose outputs a later one completed
else
  rm -f "$STAMP"
  # cargo, then wasm-bindgen's library (kerfcam-bindgen, tools/bindgen: the glue, with the arguments
  # wasm-pack 0.15 gave wasm-bindgen), then wasm-opt: the three steps wasm-pack drove, without wasm-pack
  # (issue 40: building it was 17 of a fresh machine's 54 minutes). Where kerfcam-bindgen is not installed
  # yet (a fresh machine), it is built beside the two cargo builds, which it needs only after them (fresh
  # machine, quiet: its 83 s ended before the first module's 125 s).
  bindgen_install=
  if ! bash scripts/install-bindgen.sh --check >/dev/null 2>&1; then
    (set -o pipefail; bash scripts/install-bindgen.sh 2>&1 | sed -u 's/^/[install-bindgen] /') &
    bindgen_install=$!
  fi
  # The two cargo builds share every dependency's artefacts (same profile and flags; the feature "nester"
  # only adds optional dependencies), so the second one compiles little more than the crate itself. Both
  # write the same kerfcam.wasm: the first is kept aside for the glue. The core module's glue and wasm-opt
  # run beside the nester's cargo build, whose crate is mostly one thread's work.
  wasm=${CARGO_TARGET_DIR:-target}/wasm32-unknown-unknown/$PROFILE/kerfcam.wasm
  mkdir -p www/pkg
  finish() { # MODULE: the glue (kerfcam-bindgen), then wasm-opt
    local module=$1
    echo "kerfcam-bindgen (wasm-bindgen --target web --typescript) --out-name $module"
    kerfcam-bindgen "${wasm%/*}/$module.raw.wasm" --out-dir www/pkg --out-name "$module"
    if [ "${#opt[@]}" -eq 0 ]; then
      # wasm-opt without --converge for the served build: repeating the passes until the module stops
      # shrinking is most of the build's time for a few KiB.
      # Served: -O1, a third of -Os's time for a module 4 % larger raw and 5 % smaller gzipped (the nester,
      # measured side by side on one wasm: -O1 37 s, 1,470,502 bytes, 567,351 gzipped; -Os 122 s, 1,407,797,
      # 598,461). Shipped (--dist): -Os --converge, the smallest raw modules.
      local flags=(-O1 -iit --strip-producers)
      if [ "$DIST" -eq 1 ]; then flags=(-Os --converge -iit --strip-producers); fi
      local out=www/pkg/${module}_bg.wasm
      echo "wasm-opt ${flags[*]} $out"
      wasm-opt "${flags[@]}" "$out" -o "$out.opt"
      mv "$out.opt" "$out"
    fi
  }
  cargo_module() { # MODULE: its crate build, the wasm kept aside for its glue
    local module=$1 args=()
    if [ "$module" = kerfcam ]; then
      args=(--no-default-features)
    else
      # The nester's crate (not its dependencies) at opt-level 3: the page's nest is CPU-bound and the module
      # is loaded only for Sheet mode. Measured 2026-11-30 (Node, 100 fixture plates, 15 000 evaluations,
      # the same nests; 2-core machine under load, alternating): 30.3/37.4 s at "s" against 26.4/27.4 s, and
      # the first 3 000 (the placer) 19.0/18.4 against 15.2/15.9 s; the module 840 -> 1 038 KB gzipped,
      # its crate build 76 -> 97 s of CPU.
      args=(--config "profile.$PROFILE.package.kerfcam.opt-level=3")
    fi
    echo "cargo build --lib --profile $PROFILE --target wasm32-unknown-unknown ${args[*]}"
    cargo build --lib --profile "$PROFILE" --target wasm32-unknown-unknown "${args[@]}"
    cp "$wasm" "${wasm%/*}/$module.raw.wasm"
  }
  cargo_module kerfcam
  if [ -n "$bindgen_install" ] && ! wait "$bindgen_install"; then
    echo "error: kerfcam-bindgen could not be installed (bash scripts/install-bindgen.sh says why)" >&2
    exit 1
  fi
  if [ -n "$node_install" ]; then
    if ! wait "$node_install"; then
      echo "error: node_modules could not be installed (bash scripts/install-node-modules.sh says why)" >&2
      exit 1
    fi
    node_install=
    find_wasm_opt
    key=$(sources | sha256sum | cut -d' ' -f1)
  fi
  if [ "$SERVE" -eq 1 ]; then
    # npm start (issue 40): the page is served as soon as the cutting core is ready; the nester module,
    # which only Sheet mode loads, is built meanwhile. Until it is, the server holds the nester's files
    # (www/pkg/.nester-pending names this build; scripts/serve.mjs), so Sheet mode's first request waits
    # for the module rather than getting an old one or none.
    echo $$ >"$PENDING"
    cargo_module kerfcam_nest &
    nester_build=$!
    finish kerfcam
    copy_vendor
    serve_now
    if ! wait "$nester_build"; then
      echo "error: the nester module's build failed (above); Sheet mode cannot nest until npm start succeeds" >&2
      echo "the nester module's build failed: see npm start's output" >"$FAILED"
      rm -f "$PENDING"
      wait "$SERVER_PID"
      exit 1
    fi
    finish kerfcam_nest
  else
    finish kerfcam &
    core_finish=$!
    cargo_module kerfcam_nest
    if ! wait "$core_finish"; then
      echo "error: the core module's glue or wasm-opt failed (above)" >&2
      exit 1
    fi
    finish kerfcam_nest
  fi
  if [ "$DIST" -eq 1 ]; then echo "$key dist" >"$STAMP"; else echo "$key serve" >"$STAMP"; fi
  rm -f "$PENDING"
  if [ "$SERVE" -eq 1 ]; then echo "the nester module is ready (Sheet mode): $((SECONDS - T0)) s after npm start's build began"; fi
fi

for wasm in www/pkg/kerfcam_bg.wasm www/pkg/kerfcam_nest_bg.wasm; do
  raw=$(wc -c <"$wasm")
  gz=$(gzip -9 -c "$wasm" | wc -c)
  printf '%s: %d bytes (%d KiB), gzip -9 %d bytes (%d KiB)\n' "$wasm" "$raw" $((raw / 1024)) "$gz" $((gz / 1024))
done

if [ -z "$SERVER_PID" ]; then copy_vendor; fi
if [ "$SERVE" -eq 1 ]; then
  if [ -z "$SERVER_PID" ]; then serve_now; fi
  wait "$SERVER_PID"
fi
