#!/usr/bin/env bash
# The precompute figures of docs/measurements/bench.md: a 512 x 512 patch, 40 Taylor orders (41 FFTs), first run and cached rerun,
# wall-clock time of the whole ./diffract command (JVM start included). Run: bash docs/measurements/precompute-timing.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
out=out/timing
rm -rf "$out" && mkdir -p "$out"
./diffract patch sinusoid --period 1.0 --height 0.3 --samples-per-period 32 --periods 16 --rows 512 -o "$out/p512.gsf" >/dev/null
time_of() { local s; s=$(date +%s.%N); "$@" >/dev/null 2>&1; echo "$(date +%s.%N) - $s" | bc; }
first=$(time_of ./diffract precompute --patch "$out/p512.gsf" --terms 40 -o "$out/terms")
reruns=()
for _ in 1 2 3 4 5; do reruns+=("$(time_of ./diffract precompute --patch "$out/p512.gsf" --terms 40 -o "$out/terms")"); done
best=$(printf '%s\n' "${reruns[@]}" | sort -n | head -1)
median=$(printf '%s\n' "${reruns[@]}" | sort -n | sed -n 3p)
printf 'precompute 512x512, N = 40: first run %.2f s; cached rerun median %.2f s (best %.2f s) over 5 runs; %s cores\n' \
    "$first" "$median" "$best" "$(nproc)"
