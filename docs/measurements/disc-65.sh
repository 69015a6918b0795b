#!/usr/bin/env bash
# The lobes method and its baked table under disc lights of 0.53, 2, 10 and 20 degrees against the reference's exact
# disc at the thesis' 65 um coherence, on every bench patch and the Elaphe scan (DiscReference65Measurement): the
# reference on at most 10 lit pixels of the map's line through the orders, 64 x 64 maps at theta_i = 30 degrees;
# writes docs/measurements/bench/disc-65.md. About an hour and a half on 2 cores; from anywhere: bash docs/measurements/disc-65.sh
# (PATCHES=elaphe-like DISCS=2 bash docs/measurements/disc-65.sh for a part; PIXELS=N at most N pixels per map, WIDE_SCAN_PIXELS=M
# at most M on the scan's 10- and 20-degree discs, whose reference takes 4 to 11 minutes a pixel; APPEND=1 adds to the
# lines target/disc-65.txt holds instead of starting anew; REPORT_ONLY=1 writes the page from those lines, e.g. after
# a run stopped part way).
set -euo pipefail
cd "$(dirname "$0")/../.."
patches=${PATCHES:-blazed-10um,elaphe-like,xenopeltis-like,tall,elaphe-measured,elaphe-scan}
discs=${DISCS:-0.53,2,10,20}
pixels=${PIXELS:-8}
wide_scan_pixels=${WIDE_SCAN_PIXELS:-2}
all_patches=blazed-10um,elaphe-like,xenopeltis-like,tall,elaphe-measured,elaphe-scan
report=target/disc-65.txt
mkdir -p target
measure() { # patch, discs, pixels: one run, its lines added to the report as soon as it is done
    [ -n "$2" ] || return 0
    rm -f target/test-reports/DiscReference65Measurement.txt
    mvn -B -ntp -q test -Dtest=DiscReference65Measurement -Ddiffract.measure=disc-65 \
        -Ddiffract.measure.patches="$1" -Ddiffract.measure.discs="$2" -Ddiffract.measure.maxPixels="$3"
    cat target/test-reports/DiscReference65Measurement.txt >>"$report"
}
if [ -z "${REPORT_ONLY:-}" ]; then
    [ -n "${APPEND:-}" ] || : >"$report"
    for patch in ${patches//,/ }; do
        if [ "$patch" = elaphe-scan ]; then
            narrow=$(tr , '\n' <<<"$discs" | awk '$1 < 10' | paste -sd, -)
            wide=$(tr , '\n' <<<"$discs" | awk '$1 >= 10' | paste -sd, -)
            measure "$patch" "$narrow" "$pixels"
            measure "$patch" "$wide" "$wide_scan_pixels"
        else
            measure "$patch" "$discs" "$pixels"
        fi
    done
fi
out=docs/measurements/bench/disc-65.md
{
    echo "# Disc lights at 65 um against the reference's disc"
    echo
    echo "Made by \`bash docs/measurements/disc-65.sh\` (\`DiscReference65Measurement\`): 64 x 64 maps at theta_i = 30 degrees in"
    echo "the plane of each patch's period, the thesis' 65 um coherence, pixels averaged over their boxes. A whole map"
    echo "of the reference's disc (\`DiscLightAverage\`) takes hours to days on 2 cores, so the reference is evaluated"
    echo "on at most ${pixels} lit pixels of the map's line through the orders (${wide_scan_pixels} on the scan under 10 and 20"
    echo "degrees, where it takes 4 to 11 minutes a pixel; the pixels column says how many), evenly"
    echo "spaced (every second one where there are fewer; the column through the specular for phi_i = 90, the row for"
    echo "phi_i = 0): CIEDE2000 over those pixels at the exposure the lobes method's whole map takes, for which the"
    echo "lobes method and the baked table are drawn as brdfmap draws them (the lobes' cutoff scaled to it; the last"
    echo "column). elaphe-measured is the measured patch of assets/patches"
    echo "(elaphe-100px.gwy), elaphe-scan the Elaphe-like skin at AFM size (528 x 512 samples, 52 x 51 um). The lobes"
    echo "method runs on the CPU, its baked table (the grid the commands take: 513 samples along u and v at 65 um, the"
    echo "automatic w grid, 25 samples on the scan) on the GPU, both"
    echo "from the pipeline with the commands' settings; the tall patch takes the phase-centred expansion, of which no"
    echo "table is made (dashes)."
    echo
    echo "The reference's own estimate of its error is its disc rule against the rule before it"
    echo "(\`DiscLightAverage\`; mean / max over the same pixels, and how many pixels the finest rule stopped before"
    echo "two rules agreed to 1e-4)."
    echo
    echo "| patch | disc (deg) | pixels (of lit) | lobes mean / p95 / max | baked mean / p95 / max | reference s | reference's rule: mean / max (stopped) | lobes' cutoff |"
    echo "|---|---|---|---|---|---|---|---|"
    perl -ne 'print "| $1 | $2 | $3 ($4) | $5 / $6 / $7 | $8 / $9 / $10 | $11 | $12 / $13 ($14) | $15 |\n"
        if /^(\S+), 65 um, \d+ px, ([\d.]+)-degree disc, theta_i \d+, (\d+) of the (\d+) lit pixels of \w+ \d+: lobes mean ([\d.]+), p95 ([\d.]+), max ([\d.]+); baked mean ([\d.-]+), p95 ([\d.-]+), max ([\d.-]+); reference (\d+) s, its disc rule against the one before it mean ([\d.]+), p95 [\d.]+, max ([\d.]+) \((\d+) pixels.*?(?:the lobes. cutoff (\S+) of white)?$/' \
        < <(for p in ${all_patches//,/ }; do grep "^$p, " "$report" | sort -t, -s -k4,4g || true; done)
    echo
    echo "Rows a run did not reach are missing; the reference's seconds are wall time on this machine: $(nproc) CPU"
    echo "cores ($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1))."
} >"$out"
cat "$out"
