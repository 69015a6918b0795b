#!/usr/bin/env bash
# GPU ms/frame and CIEDE2000 to the CPU reference of FLSS in the thesis' configuration, with the
# per-lookup Taylor early stop, with the automatic window, and with both (128 x 128 maps, theta_i 30, the patches of
# docs/measurements/gpu-figures.sh). Prints a markdown table. Run from the repository root: bash docs/measurements/early-stop-timing.sh
set -euo pipefail
run() { ./diffract "$@"; }
mkdir -p out/early-stop
run patch blazed --period 2.5 --height 0.2 --samples-per-period 25 --periods 26 --rows 16 \
    -o out/early-stop/blazed.gsf >/dev/null
run patch elaphe-like -o out/early-stop/elaphe-like.gsf >/dev/null
echo "| patch | setting | GPU ms/frame | CIEDE2000 to reference: disk mean; lit mean / p95 |"
echo "|---|---|---|---|"
for spec in "blazed 15 0" "elaphe-like 25 90"; do
    read -r name exposure phi <<<"$spec"
    common=(--patch "out/early-stop/$name.gsf" --theta-i 30 --phi-i "$phi" --exposure "$exposure" --size 128)
    run brdfmap "${common[@]}" --variant reference -o "out/early-stop/$name-ref.png" \
        --pfm "out/early-stop/$name-ref.pfm" >/dev/null 2>&1
    for setting in "fixed:" "tolerance 1e-4:--taylor-tolerance 1e-4" "automatic window:--window-radius auto" \
                   "both:--taylor-tolerance 1e-4 --window-radius auto"; do
        label="${setting%%:*}"
        read -r -a extra <<<"${setting#*:}"
        ms=$(run brdfmap "${common[@]}" --variant flss --engine gpu --time "${extra[@]}" \
            -o "out/early-stop/$name-x.png" --pfm "out/early-stop/$name-x.pfm" 2>/dev/null \
            | sed -n 's/^gpu \([0-9.]*\) ms.*/\1/p')
        diff=$(run compare "out/early-stop/$name-x.pfm" "out/early-stop/$name-ref.pfm" --exposure "$exposure" \
            | sed -n 's/.*CIEDE2000 mean \([0-9.]*\),.*lit: mean \([0-9.]*\), p95 \([0-9.]*\),.*/\1; \2 \/ \3/p')
        echo "| $name | $label | $ms | $diff |"
    done
done
