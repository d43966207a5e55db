#!/usr/bin/env bash
# Builds the release wasm and its JS glue into www/pkg (kerfcam.js + kerfcam_bg.wasm) and prints its size.
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

wasm-pack build "${opt[@]}" --target web --release --out-dir www/pkg --out-name kerfcam

wasm=www/pkg/kerfcam_bg.wasm
raw=$(wc -c <"$wasm")
gz=$(gzip -9 -c "$wasm" | wc -c)
printf '%s: %d bytes (%d KiB), gzip -9 %d bytes (%d KiB)\n' "$wasm" "$raw" $((raw / 1024)) "$gz" $((gz / 1024))

# The page's one third-party module, fflate (MIT; zips the batch's programs), copied from node_modules so
# the page loads it from its own origin (no CDN) and the service worker can keep it offline.
mkdir -p www/vendor
cp node_modules/fflate/esm/browser.js www/vendor/fflate.js
echo "www/vendor/fflate.js: fflate $(node -p "require('./node_modules/fflate/package.json').version")"
