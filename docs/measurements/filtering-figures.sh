#!/usr/bin/env bash
# The pictures of docs/measurements/filtering.md: 64 x 64 BRDF maps at the thesis' 65 um coherence, theta_i = 30 degrees, of the
# Elaphe-like patch and (when present) the measured Elaphe patch: the filtered reference, FLSS in the thesis'
# configuration (point-sampled), the lobes method, the lobes method at 512 x 512, and the reference under a 2-degree
# light, all at the reference's auto exposure; for the README, 128 x 128 maps of the measured patch by FLSS in the
# thesis' configuration, the lobes method and the reference. Run from anywhere: bash docs/measurements/filtering-figures.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=docs/images
tmp=out/filtering-figures
mkdir -p "$tmp" "$out"
./diffract patch elaphe-like -o "$tmp/elaphe-like.gsf" >/dev/null
patches=("elaphe-like|--patch $tmp/elaphe-like.gsf")
ELAPHE=assets/patches/elaphe-100px.png
patches+=("elaphe-100px|--patch $ELAPHE --max-height 0.375 --pixel-size 0.0686")
for entry in "${patches[@]}"; do
    IFS='|' read -r name args <<<"$entry"
    common="$args --theta-i 30 --phi-i 90"
    # shellcheck disable=SC2086
    exposure=$(./diffract brdfmap $common --variant reference --size 64 --exposure auto \
        -o "$out/filtering-$name-reference-64.png" 2>&1 | sed -n 's/.*auto exposure \([0-9.e+-]*\).*/\1/p')
    echo "$name: reference exposure $exposure"
    # shellcheck disable=SC2086
    ./diffract brdfmap $common --variant flss --size 64 --exposure "$exposure" -o "$out/filtering-$name-flss-64.png"
    # shellcheck disable=SC2086
    ./diffract brdfmap $common --variant lobes --size 64 --exposure "$exposure" -o "$out/filtering-$name-lobes-64.png"
    # shellcheck disable=SC2086
    ./diffract brdfmap $common --variant lobes --engine gpu --size 512 --exposure "$exposure" \
        -o "$out/filtering-$name-lobes-512.png"
    # shellcheck disable=SC2086
    ./diffract brdfmap $common --variant reference --light-size-deg 2 --size 64 --exposure "$exposure" \
        -o "$out/filtering-$name-reference-2deg-64.png"
done
P="--patch $ELAPHE --max-height 0.375 --pixel-size 0.0686 --theta-i 30 --phi-i 90 --size 128"
# shellcheck disable=SC2086
exposure=$(./diffract brdfmap $P --exposure auto -o "$out/filtering-elaphe-100px-reference-128.png" 2>&1 \
    | sed -n 's/.*auto exposure \([0-9.e+-]*\).*/\1/p')
for variant in flss lobes; do
    # shellcheck disable=SC2086
    ./diffract brdfmap $P --variant $variant --exposure "$exposure" -o "$out/filtering-elaphe-100px-$variant-128.png"
done
