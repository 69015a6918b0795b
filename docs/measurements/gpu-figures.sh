#!/usr/bin/env bash
# Regenerates the pictures and the numbers of docs/measurements/gpu.md from the repository root: bash docs/measurements/gpu-figures.sh
# Needs OpenGL 3.3 (without a display the GPU commands run on headless EGL, docs/guide/headless-gl.md).
# Prints the table of docs/measurements/gpu.md (ms/frame on this machine's GL, CIEDE2000 against the CPU reference) to stdout.
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p docs/images out/figures
run() { echo "+ ./diffract $*" >&2; ./diffract "$@"; }

run patch blazed --period 2.5 --height 0.2 --samples-per-period 25 --periods 26 --rows 16 \
    -o out/figures/blazed.gsf >/dev/null
run patch elaphe-like -o out/figures/elaphe-like.gsf >/dev/null

SIZE=256
echo "| patch | variant | GPU ms/frame (${SIZE}x${SIZE}) | CIEDE2000 mean | p95 | lit pixels | CIEDE2000 mean (lit) | p95 (lit) |"
echo "|---|---|---|---|---|---|---|---|"
# name, exposure, light: the same views as docs/measurements/figures.sh (theta_i = 30 degrees in the plane of the period)
for spec in "blazed 15 0" "elaphe-like 25 90"; do
    read -r name exposure phi <<<"$spec"
    common=(--patch "out/figures/$name.gsf" --theta-i 30 --phi-i "$phi" --exposure "$exposure" --size "$SIZE")
    run brdfmap "${common[@]}" --variant reference -o "docs/images/gpu-$name-reference-30.png" \
        --pfm "out/figures/$name-reference.pfm" >/dev/null
    for variant in flss nmm pq; do
        timing=$(run brdfmap "${common[@]}" --variant "$variant" --engine gpu --time \
            -o "docs/images/gpu-$name-$variant-30.png" --pfm "out/figures/$name-$variant-gpu.pfm" \
            2>out/figures/gpu-stderr.txt | grep '^gpu ')
        ms=$(sed -E 's/^gpu ([0-9.]+) ms.*/\1/' <<<"$timing")
        stats=$(run compare "out/figures/$name-$variant-gpu.pfm" "out/figures/$name-reference.pfm" \
            --exposure "$exposure")
        # "CIEDE2000 mean M, p95 P, ... over N pixels; lit: mean M, p95 P, ... over L pixels (exposure E)"
        all=${stats%%; lit:*}
        lit=${stats##*; lit:}
        field() { sed -E "s/.*$1 ([0-9.-]+)[, ].*/\1/" <<<"$2"; }
        count=$(sed -E 's/.* over ([0-9]+) pixels.*/\1/' <<<"$lit")
        echo "| $name | $variant | $ms | $(field mean "$all") | $(field p95 "$all") | $count |" \
            "$(field mean "$lit") | $(field p95 "$lit") |"
    done
done
echo
echo "Machine: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')), \
$(grep -m1 '^GPU:' out/figures/gpu-stderr.txt | sed 's/^GPU: //')"
