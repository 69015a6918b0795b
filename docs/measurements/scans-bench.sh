#!/usr/bin/env bash
# Regenerates docs/measurements/bench/scans-64.md and scans-256.md (and their CSVs), the measurements of docs/measurements/scans.md, from the
# repository root: bash docs/measurements/scans-bench.sh
# The 52 um elaphe-scan (528 x 512 samples) at the thesis' 65 um coherence, theta_i = 30, a point light: the lobes
# method on the GPU, FLSS in the thesis' configuration and the baked table against the filtered reference (window
# averaged over its position), with the reference's and the bake's seconds. The 64 px reference takes about 5 minutes
# on 2 idle cores, the 256 px one about an hour; reference maps are kept in the disk cache (docs/guide/faults.md).
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p docs/measurements/bench
for size in 64 256; do
    ./diffract bench --filtering --patches elaphe-scan --size "$size" --lights 0 -o "out/scans-$size"
    cp "out/scans-$size/filtering.md" "docs/measurements/bench/scans-$size.md"
    cp "out/scans-$size/filtering.csv" "docs/measurements/bench/scans-$size.csv"
done
