#!/usr/bin/env bash
# The accuracy table of docs/measurements/accuracy.md: each CPU variant's colour BRDF map against the exact reference (CIEDE2000 over the
# unit disk, after the display exposure). Run from anywhere: bash docs/measurements/accuracy.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=out/accuracy
mkdir -p "$out"
./diffract patch blazed --period 2.5 --height 0.2 --samples-per-period 25 --periods 26 --rows 16 -o "$out/blazed.gsf" >/dev/null
patches=("blazed|--patch $out/blazed.gsf|0|15")
ELAPHE=assets/patches/elaphe-100px.png
patches+=("elaphe|--patch $ELAPHE --max-height 0.375 --pixel-size 0.0686|90|25")
echo "| patch | theta_i | variant | seconds | CIEDE2000 to reference: unit disk; lit pixels (exposure) |"
echo "|---|---|---|---|---|"
for entry in "${patches[@]}"; do
    IFS='|' read -r name args phi exposure <<<"$entry"
    for theta in 30 75; do
        for variant in reference flss nmm pq; do
            start=$(date +%s.%N)
            # shellcheck disable=SC2086
            ./diffract brdfmap $args --theta-i "$theta" --phi-i "$phi" --variant "$variant" --size 128 \
                -o "$out/$name-$theta-$variant.png" --pfm "$out/$name-$theta-$variant.pfm" >/dev/null 2>&1
            seconds=$(echo "$(date +%s.%N) - $start" | bc)
            if [ "$variant" = reference ]; then
                printf '| %s | %s | %s | %.1f | - |\n' "$name" "$theta" "$variant" "$seconds"
            else
                result=$(./diffract compare "$out/$name-$theta-$variant.pfm" "$out/$name-$theta-reference.pfm" --exposure "$exposure")
                printf '| %s | %s | %s | %.1f | %s |\n' "$name" "$theta" "$variant" "$seconds" "${result#CIEDE2000 }"
            fi
        done
    done
done
