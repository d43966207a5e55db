#!/usr/bin/env bash
# Builds the release wasm modules and their JS glue into www/pkg (kerfcam.js + kerfcam_bg.wasm, the cutting
# core; kerfcam_nest.js + kerfcam_nest_bg.wasm, the nester) and prints their sizes.
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
export PATH="$HOME/.cargo/bin:$PATH"

# wasm-pack runs the wasm-opt it finds on PATH (and would try to download one otherwise, which fails offline).
# The npm package binaryen (installed by scripts/setup.sh) comes first: Debian 12's binaryen 108 writes
# wasm-bindgen's externref table in an outdated encoding that browsers refuse
# ("WebAssembly.Table.set(): Argument 1 is invalid for table"), so a system wasm-opt older than 116 is skipped.
export PATH="$PWD/node_modules/.bin:$PATH"
opt=()
version=$(wasm-opt --version 2>/dev/null | grep -oE '[0-9]+' | head -n 1 || true)
if [ -z "$version" ]; then
  echo "note: no wasm-opt on PATH; building without it"
  opt=(--no-opt)
elif [ "$version" -lt 116 ]; then
  echo "note: wasm-opt $version is too old (needs binaryen >= 116); building without it"
  opt=(--no-opt)
else
  echo "wasm-opt: $(command -v wasm-opt) (binaryen $version)"
fi

# The wasm modules are built for size (opt-level "s"; Cargo.toml's release profile is 3, for the native CLI).
export CARGO_PROFILE_RELEASE_OPT_LEVEL=s

# Two modules from the one crate (issue 17): the cutting core (kerfcam, without the feature "nester"),
# which the page loads at once, and the same pipeline with the nesting engine (kerfcam_nest), which the
# worker loads only when Sheet mode first needs the nester.
wasm-pack build "${opt[@]}" --target web --release --out-dir www/pkg --out-name kerfcam -- --no-default-features
wasm-pack build "${opt[@]}" --target web --release --out-dir www/pkg --out-name kerfcam_nest

for wasm in www/pkg/kerfcam_bg.wasm www/pkg/kerfcam_nest_bg.wasm; do
  raw=$(wc -c <"$wasm")
  gz=$(gzip -9 -c "$wasm" | wc -c)
  printf '%s: %d bytes (%d KiB), gzip -9 %d bytes (%d KiB)\n' "$wasm" "$raw" $((raw / 1024)) "$gz" $((gz / 1024))
done

# The page's one third-party module, fflate (MIT; zips the batch's programs), copied from node_modules so
# the page loads it from its own origin (no CDN) and the service worker can keep it offline.
mkdir -p www/vendor
cp node_modules/fflate/esm/browser.js www/vendor/fflate.js
echo "www/vendor/fflate.js: fflate $(node -p "require('./node_modules/fflate/package.json').version")"
