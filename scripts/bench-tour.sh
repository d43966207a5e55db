#!/usr/bin/env bash
# The contour order against LKH-3 (issue 17 item 2): random placements of
# 100, 500, 1,000 and 5,000 parts (or the sizes given), our tour from
# `cargo bench --bench tsp`, LKH-3's through the same pierce points from
# tests/reference/lkh_tsp.py; prints kerfcam / LKH per size ("ratio").
#
#   bash scripts/bench-tour.sh [PARTS ...]
#
# Makes a venv with elkai (LKH-3) and numpy under target/bench-venv-lkh
# (pip, once). A benchmark, not a test: it asserts nothing. LKH takes
# ~4 min on the 5,000-part nest here. Figures: benches/tsp.rs (latest,
# 2026-11-24: ours / LKH-3 1.000, 1.000, 1.012 (c), 1.019 (c) at 100, 500,
# 1,000, 5,000 random parts; 60k sites in 290–310 ms CPU, 1.024–1.038 of
# the long search; A/B timing: `cargo bench --bench tsp -- --time`;
# fourth pass, sites in sheet order and flat lists: 60k sites 0.81-0.85x
# CPU, 220-230 ms; tours unchanged at every size; fifth pass, no kicks
# above 20k sites: 60k sites 0.76-0.83x CPU, tours +0.3 % there, unchanged
# up to 20k sites, so the LKH-3 ratios stand; sixth pass, session 12:
# the plan stage 0.84-0.92x CPU on the 4/11/25 MB nests, 60k sites
# 180-200 ms CPU at load 7, tours unchanged at every size, so the LKH-3
# ratios stand again).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
sizes=("$@")
[ ${#sizes[@]} -gt 0 ] || sizes=(100 500 1000 5000)

venv=target/bench-venv-lkh
if [ ! -x "$venv/bin/python" ] || ! "$venv/bin/python" -c 'import elkai, numpy' 2>/dev/null; then
  python3 -m venv "$venv"
  "$venv/bin/pip" install --quiet elkai numpy
fi

cargo bench --quiet --bench tsp -- "${sizes[@]}"
files=()
for n in "${sizes[@]}"; do files+=("target/tsp-bench/random-$n.json"); done
echo
"$venv/bin/python" tests/reference/lkh_tsp.py "${files[@]}"
