#!/usr/bin/env bash
# Regenerates docs/measurements/bench.md's tables and plot from the repository root: bash docs/measurements/bench.sh
# The full sweep (540 configurations, the baked table and the lean rows included) takes about 15-20 minutes on
# 2 cores with Mesa llvmpipe; OpenGL 3.3 is needed (headless EGL without a display, docs/guide/headless-gl.md).
# Reference maps are kept in the disk cache (~/.cache/diffract, docs/guide/faults.md). On a GPU, `./diffract bench --gpu-suite -o DIR` is the
# short table (docs/guide/headless-gl.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
./diffract bench --coherence-length 10 -o out/bench
mkdir -p docs/images docs/measurements/bench
cp out/bench/pareto.png docs/images/bench-pareto.png
cp out/bench/results.csv out/bench/results.md out/bench/pareto.md out/bench/targets.md out/bench/machine.txt docs/measurements/bench/
cat out/bench/targets.md out/bench/pareto.md

