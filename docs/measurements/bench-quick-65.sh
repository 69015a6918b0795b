#!/usr/bin/env bash
# The quick sweep at the thesis' 65 um coherence (bench's default), every bench patch: the targets table into
# docs/measurements/bench/quick-65.md. A few minutes on llvmpipe.
set -euo pipefail
cd "$(dirname "$0")/../.."
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
./diffract bench --quick -o "$out" > "$out/log.txt"
{
    echo "# The quick sweep at 65 um"
    echo
    echo "Made by \`bash docs/measurements/bench-quick-65.sh\` (\`./diffract bench --quick\`: 64 x 64 maps, theta_i 0, 45 and 75"
    echo "degrees, CIEDE2000 over lit pixels against the filtered reference); $(cat "$out/machine.txt")."
    echo "The lobes method sums the expansion the pipeline chooses (the phase-centred one on the tall patch, where"
    echo "the thesis' series of N = 30 does not converge); FLSS, NMM and PQ the thesis' series."
    echo
    cat "$out/targets.md"
} > docs/measurements/bench/quick-65.md
cat docs/measurements/bench/quick-65.md
