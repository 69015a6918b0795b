#!/usr/bin/env bash
# Times the user's path as README shows it, from an empty disk cache (a temporary DIFFRACT_CACHE), each command run
# twice: the demo without a screen, and the Elaphe scene rendered at 320 x 200. Writes docs/measurements/user-path.md.
set -euo pipefail
cd "$(dirname "$0")/../.."
./diffract --version > /dev/null  # builds the jar first, outside the timings
cache=$(mktemp -d)
out=$(mktemp -d)
trap 'rm -rf "$cache" "$out"' EXIT
export DIFFRACT_CACHE="$cache"
unset DISPLAY
rows=()
timed() {  # label, command...: one row with the wall time and what the run said about the table
    local label=$1; shift
    local start end log
    log="$out/log.txt"
    start=$(date +%s.%N)
    "$@" > "$log" 2>&1
    end=$(date +%s.%N)
    local table
    table=$(grep -oE "(baked|loaded) the [0-9x ]+ table|baked [0-9x ]+ table" "$log" | head -1 || true)
    rows+=("| $label | \`$(echo "$*" | sed "s#$out#out#g")\` | $(printf '%.1f' "$(echo "$end - $start" | bc)") | ${table:-no table} |")
}
timed "demo, first run" ./diffract demo -o "$out/demo"
timed "demo, second run" ./diffract demo -o "$out/demo"
timed "render, first run" ./diffract render assets/scenes/snake-elaphe.json --size 320x200 -o "$out/snake.png"
timed "render, second run" ./diffract render assets/scenes/snake-elaphe.json --size 320x200 -o "$out/snake.png"
{
    echo "# The user's path, timed"
    echo
    echo "Made by \`bash docs/measurements/user-path.sh\` on $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs)),"
    echo "$(java -jar target/diffract.jar --version 2>/dev/null | head -1), DISPLAY unset, from an empty disk cache."
    echo "Seconds of wall time per command, the JVM's start included; a busy machine takes 2-5 times longer."
    echo
    echo "| run | command | seconds | the table |"
    echo "| --- | --- | ---: | --- |"
    printf '%s\n' "${rows[@]}"
    echo
    echo "The first run bakes the lobes method's table of the scene's patch (with its progress and time left) and"
    echo "stores it in the disk cache ([faults.md](../guide/faults.md#the-disk-cache)); later runs load it."
} > docs/measurements/user-path.md
cat docs/measurements/user-path.md
