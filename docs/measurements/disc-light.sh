#!/usr/bin/env bash
# The table of docs/measurements/filtering.md, "The disc against the Gaussian": CIEDE2000 (mean / p95 over the lit pixels, at the
# Gaussian map's auto exposure) between the reference under a disc light and under the Gaussian profile of the same
# diameter, for the blazed grating (blazed-10um) and the Elaphe-like patch, at 0.53, 2, 10 and 20 degrees; theta_i =
# 30 degrees in the plane of each patch's period. SIZE (default 16) and COHERENCE_UM (default 10) keep the run to a
# few minutes on 2 cores: the disc integrates every direction by the reference, so its cost grows with the light's
# size and the coherence length. PATCHES and LIGHTS choose the rows (default: both patches, all four sizes); APPEND=1
# adds rows to the table instead of starting it. Writes docs/measurements/bench/disc-light.md. Run from anywhere:
# bash docs/measurements/disc-light.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
SIZE=${SIZE:-16}
COHERENCE_UM=${COHERENCE_UM:-10}
PATCHES=${PATCHES:-"blazed-10um elaphe-like"}
LIGHTS=${LIGHTS:-"0.53 2 10 20"}
APPEND=${APPEND:-0}
tmp=out/disc-light
mkdir -p "$tmp" docs/measurements/bench
table=docs/measurements/bench/disc-light.md
./diffract patch blazed-10um -o "$tmp/blazed-10um.gsf" >/dev/null
./diffract patch elaphe-like -o "$tmp/elaphe-like.gsf" >/dev/null
[ "$APPEND" = 1 ] || {
    echo "$SIZE x $SIZE BRDF maps, theta_i = 30 degrees, coherence length $COHERENCE_UM um, the reference (box pixels):"
    echo "CIEDE2000 mean / p95 over the lit pixels between the disc and the Gaussian profile of the same diameter"
    echo
    echo "| patch | light (deg) | lit px | disc vs gaussian | gaussian s | disc s |"
    echo "|---|---|---|---|---|---|"
} >"$table"
for name in $PATCHES; do
    phi=0
    [ "$name" = elaphe-like ] && phi=90 # the light in the plane of the patch's period
    for d in $LIGHTS; do
        common="--patch $tmp/$name.gsf --theta-i 30 --phi-i $phi --variant reference --size $SIZE"
        common="$common --coherence-length $COHERENCE_UM --light-size-deg $d"
        start=$(date +%s.%N)
        # shellcheck disable=SC2086
        exposure=$(./diffract brdfmap $common --light-profile gaussian --exposure auto -o "$tmp/$name-$d-g.png" \
            --pfm "$tmp/$name-$d-g.pfm" 2>&1 | sed -n 's/.*auto exposure \([0-9.e+-]*\).*/\1/p')
        mid=$(date +%s.%N)
        # shellcheck disable=SC2086
        ./diffract brdfmap $common --light-profile disc --exposure "$exposure" -o "$tmp/$name-$d-d.png" \
            --pfm "$tmp/$name-$d-d.pfm" >/dev/null 2>&1
        end=$(date +%s.%N)
        line=$(./diffract compare "$tmp/$name-$d-d.pfm" "$tmp/$name-$d-g.pfm" --exposure "$exposure")
        lit=$(sed -n 's/.*lit: mean \([0-9.]*\), p95 \([0-9.]*\),.* over \([0-9]*\) pixels.*/\1 \/ \2|\3/p' <<<"$line")
        IFS='|' read -r stats count <<<"$lit"
        printf '| %s | %s | %s | %s | %.1f | %.1f |\n' "$name" "$d" "$count" "$stats" \
            "$(echo "$mid - $start" | bc)" "$(echo "$end - $mid" | bc)" >>"$table"
        echo "$name $d deg: $line"
    done
done
# appending: the old footer goes, and the blank line above it, so that the new rows join the table
[ "$APPEND" = 1 ] && sed -i '/CPU cores/d' "$table" && sed -i -e :a -e '/^\n*$/{$d;N;ba' -e '}' "$table"
echo >>"$table"
echo "$(nproc) CPU cores ($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1))" >>"$table"
cat "$table"
