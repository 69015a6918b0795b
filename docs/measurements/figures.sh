#!/usr/bin/env bash
# Regenerates the BRDF-map pictures of README.md and docs/measurements/accuracy.md from the repository root: bash docs/measurements/figures.sh
# The Elaphe pictures show the measured patch of assets/patches. They are drawn at a 10 um
# coherence, where the thesis' point-sampling approximations are valid, with pixels sampled at their centres as the
# thesis' maps are (docs/measurements/filtering.md has the 65 um pictures, pixels averaged).
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p docs/images out/figures
run() { echo "+ ./diffract $*" >&2; ./diffract "$@" >/dev/null; }

run patch blazed --period 2.5 --height 0.2 --samples-per-period 25 --periods 26 --rows 16 -o out/figures/blazed.gsf
for variant in reference flss nmm pq; do
    run brdfmap --patch out/figures/blazed.gsf --theta-i 30 --coherence-length 10 --pixel-filter point --variant "$variant" --exposure 15 --size 256 \
        -o "docs/images/blazed-$variant-30.png"
done
run brdfmap --patch out/figures/blazed.gsf --theta-i 75 --coherence-length 10 --pixel-filter point --variant reference --exposure auto --size 256 \
    -o docs/images/blazed-reference-75.png
run brdfmap --patch out/figures/blazed.gsf --theta-i 30 --coherence-length 10 --pixel-filter point --lambda 550 --variant reference --exposure auto --size 256 \
    -o docs/images/blazed-reference-30-550nm.png

ELAPHE=assets/patches/elaphe-100px.png
for variant in reference flss nmm pq; do
    run brdfmap --patch "$ELAPHE" --max-height 0.375 --pixel-size 0.0686 --theta-i 30 --phi-i 90 --coherence-length 10 --pixel-filter point \
        --variant "$variant" --exposure 25 --size 256 -o "docs/images/elaphe-$variant-30.png"
done
run brdfmap --patch "$ELAPHE" --max-height 0.375 --pixel-size 0.0686 --theta-i 75 --phi-i 90 --coherence-length 10 --pixel-filter point \
    --variant reference --exposure auto --size 256 -o docs/images/elaphe-reference-75.png
