#!/usr/bin/env bash
# Regenerates docs/measurements/bench/filtering.md and filtering.csv (the filtering targets of docs/measurements/filtering.md) from the
# repository root: bash docs/measurements/filtering-bench.sh
# At the thesis' 65 um coherence, per bench patch and the measured Elaphe patch (assets/patches), for a
# point light and a 2-degree light: the lobes method, FLSS in the thesis' configuration and the baked table against
# the filtered reference, and their GPU times on one context. About 10 minutes on 2 cores with llvmpipe; reference
# maps and baked tables are kept in the disk cache (~/.cache/diffract, docs/guide/faults.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
ELAPHE=assets/patches/elaphe-100px.png
./diffract bench --filtering -o out/filtering --patch "$ELAPHE" --max-height 0.375 --pixel-size 0.0686 --phi-i 90
mkdir -p docs/measurements/bench
cp out/filtering/filtering.md out/filtering/filtering.csv docs/measurements/bench/
