#!/usr/bin/env bash
# What the lobes method's cutoff changes: for every synthetic patch (the 52 um elaphe-scan at 256 px, the others at
# 128 px; GPU, theta_i = 30, point light) the map at the default cutoff against the map with none, and the same for a
# cutoff ten times coarser, CIEDE2000 over all pixels and the lit ones at an exposure of 30. Into docs/measurements/bench/cutoff.md:
# bash docs/measurements/cutoff.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
lit() { ./diffract compare --exposure 30 "$1" "$2" | sed -n 's/.*lit: mean \([^,]*\), p95 \([^,]*\), p99 [^,]*, max \([^ ]*\) over \([0-9]*\) pixels.*/\1 \/ \2 \/ \3 (\4 px)/p'; }
all() { ./diffract compare --exposure 30 "$1" "$2" | sed -n 's/^CIEDE2000 mean \([^,]*\), p95 \([^,]*\), p99 [^,]*, max \([^ ]*\) over.*/\1 \/ \2 \/ \3/p'; }
{
    echo "# The lobes method's cutoff"
    echo
    echo "Made by \`bash docs/measurements/cutoff.sh\`: \`brdfmap --variant lobes --engine gpu\` at theta_i = 30 under a point light,"
    echo "the default cutoff (3e-6 of white) and 1e-5 each against no cutoff (\`--lobe-quadrature cutoff=0\`), CIEDE2000"
    echo "mean / p95 / max at an exposure of 30, over the whole map and over its lit pixels (Y above 1 % of white in"
    echo "either map); $(nproc) CPU cores, $(./diffract brdfmap --synthetic blazed --variant lobes --engine gpu --size 8 \
        -o "$out/gpu.png" 2>&1 | sed -n 's/^GPU: //p')."
    echo
    echo "| patch | map | default, all pixels | default, lit pixels | 1e-5, all pixels | 1e-5, lit pixels |"
    echo "|---|---|---|---|---|---|"
    for patch in elaphe-like xenopeltis-like blazed sinusoid tall blazed-10um elaphe-scan; do
        size=128
        [ "$patch" = elaphe-scan ] && size=256
        for cutoff in 0 default 1e-5; do
            quadrature=()
            [ "$cutoff" != default ] && quadrature=(--lobe-quadrature "cutoff=$cutoff")
            ./diffract brdfmap -q --synthetic "$patch" --variant lobes --engine gpu --size "$size" "${quadrature[@]}" \
                --pfm "$out/$patch-$cutoff.pfm" -o "$out/$patch-$cutoff.png" > /dev/null
        done
        echo "| $patch | $size px | $(all "$out/$patch-0.pfm" "$out/$patch-default.pfm") |" \
            "$(lit "$out/$patch-0.pfm" "$out/$patch-default.pfm") |" \
            "$(all "$out/$patch-0.pfm" "$out/$patch-1e-5.pfm") | $(lit "$out/$patch-0.pfm" "$out/$patch-1e-5.pfm") |"
    done
} > docs/measurements/bench/cutoff.md
cat docs/measurements/bench/cutoff.md
