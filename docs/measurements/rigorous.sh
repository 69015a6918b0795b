#!/usr/bin/env bash
# The fast path against Maxwell's equations (docs/design/rigorous.md): runs GainModelsMeasurement (the cheap gains against
# the rigorous orders) and RigorousMeasurement (64 x 64 maps of the
# Elaphe-like and Xenopeltis-like ridges and of the blazed grating under the sun's disc at 0 and 30 degrees: the lobes
# method with Rayleigh-Rice's gain, with Stam's and with the rigorous orders, each against the rigorous method) with an
# empty cache of rigorous orders, so the times include the solves and the tables; times brdfmap's GPU path with the
# rigorous orders; writes docs/measurements/rigorous-measurements.md and docs/images/rigorous-*.png. About an hour on 2 cores;
# from anywhere: bash docs/measurements/rigorous.sh (--report-only writes the page again from the last run's reports, timing
# the GPU's maps where they were not timed yet)
set -euo pipefail
cd "$(dirname "$0")/../.."
out=docs/measurements/rigorous-measurements.md
if [ "${1:-}" != --report-only ]; then
    rm -rf target/test-cache/rigorous-orders target/test-cache/order-corrections target/test-reports/rigorous
    rm -f target/test-reports/RigorousMeasurement.txt target/test-reports/GainModelsMeasurement.txt
    mvn -B -ntp -q test -Dtest='GainModelsMeasurement,RigorousMeasurement' -Ddiffract.measure=rigorous
    mkdir -p docs/images
    cp target/test-reports/rigorous/rigorous-*.png docs/images/
fi
if [ "${1:-}" != --report-only ] || [ ! -s out/rigorous-gpu.txt ]; then
    mkdir -p out
    # the GPU's map with the rigorous orders, after the table is in the user's cache (the first run solves it)
    ./diffract brdfmap --synthetic elaphe-ridge --variant lobes --orders rigorous --theta-i 30 --size 64 --engine gpu \
        -o out/rigorous-gpu.png --exposure auto --time > out/rigorous-gpu.txt 2>&1 || { cat out/rigorous-gpu.txt; exit 1; }
    ./diffract brdfmap --synthetic elaphe-ridge --variant lobes --theta-i 30 --size 64 --engine gpu \
        -o out/rigorous-gpu-scalar.png --exposure auto --time > out/rigorous-gpu-scalar.txt 2>&1 || { cat out/rigorous-gpu-scalar.txt; exit 1; }
fi
{
    echo "# The scalar model's gain and the lobes method's orders against Maxwell's equations"
    echo
    echo "Made by \`bash docs/measurements/rigorous.sh\` (\`RigorousMeasurement\`): 64 x 64 BRDF maps under the sun's disc (0.53"
    echo "degrees, pixel boxes, 380-780 nm, n = 1.56), the light at 0 and 30 degrees in the plane of the period, at the"
    echo "default resolution (harmonics up to 2 period / lambda + 12, 24 layers extrapolated from 12). Each of the lobes"
    echo "method's maps against the rigorous method's: CIEDE2000 over the lit pixels at the rigorous map's auto exposure,"
    echo "and the CPU seconds of the map. The first rigorous map of a direction solves its orders; the first map of a"
    echo "patch with the rigorous orders solves its table (21 wavelengths x the light's directions), which the disk"
    echo "cache keeps for every later map, scene and shader; the second theta_i shows the map alone."
    echo
    echo "## The gain: the cheap corrections against the rigorous orders"
    echo
    echo "\`GainModelsMeasurement\`: keratin gratings lit at 0, 30 and 60 degrees, at 450, 550 and 650 nm; each order that"
    echo "carries at least 5 % of the diffracted power, the scalar efficiency with each candidate gain against the"
    echo "rigorous one (the Fourier modal method at the default resolution): worst and median relative error."
    echo
    echo "| relief | orders | Stam (Schlick, shadowing) | Stam, Fresnel's reflectance | Stam, Fresnel's, no shadowing | Rayleigh-Rice (the default) | Rayleigh-Rice, shadowing |"
    echo "|---|---|---|---|---|---|---|"
    perl -ne 'if (/^(.*?): (.*) \((\d+) orders\)/) { my ($r, $rest, $n) = ($1, $2, $3);
        my @c = ($rest =~ /worst ([-+\d]+ %), median (\d+ %)/g); my @cells;
        while (@c) { my $w = shift @c; my $m = shift @c; push @cells, "$w / $m"; }
        print "| $r | $n | " . join(" | ", @cells) . " |\n"; }' target/test-reports/GainModelsMeasurement.txt
    echo
    echo "## The lobes method's orders against the rigorous map"
    echo
    echo "| patch | theta_i | rigorous map | lobes (Rayleigh-Rice) | lobes, Stam's gain | lobes, rigorous orders | rigorous orders vs scalar (lobes) |"
    echo "|---|---|---|---|---|---|---|"
    perl -e '
        my (%rig, %m, @keys);
        while (<>) {
            if (/^(\S+), (\d+) deg, rigorous: ([\d.]+) s/) { push @keys, "$1|$2"; $rig{"$1|$2"} = $3; }
            elsif (/^(\S+), (\d+) deg, (.*?): lit mean ([\d.]+), p95 ([\d.]+) over (\d+) pixels, ([\d.]+) s/) {
                $m{"$1|$2"}{$3} = "$4 / $5 ($7 s)"; }
            elsif (/^(\S+), (\d+) deg, the rigorous orders against the scalar ones: lit mean ([\d.]+), p95 ([\d.]+)/) {
                $m{"$1|$2"}{"change"} = "$3 / $4"; }
        }
        for my $k (@keys) {
            my ($p, $t) = split /\|/, $k;
            printf "| %s | %s | %s s | %s | %s | %s | %s |\n", $p, $t, $rig{$k}, $m{$k}{"lobes"},
                $m{$k}{"lobes, Stam\x27s gain"}, $m{$k}{"lobes, rigorous orders"}, $m{$k}{"change"};
        }' target/test-reports/RigorousMeasurement.txt
    echo
    echo "CIEDE2000 lit mean / p95 (CPU seconds). The pictures: the rigorous map, the lobes method with the scalar"
    echo "orders, and with the rigorous orders, at one exposure (the rigorous map's):"
    echo
    for f in target/test-reports/rigorous/rigorous-*.png; do
        b=$(basename "$f" .png)
        echo "![${b#rigorous-}](../images/$b.png)"
        echo
    done
    echo "On the GPU (\`brdfmap --engine gpu --time\`, the Elaphe-like ridge at 30 degrees, 64 x 64; GL time on"
    echo "$(grep -o 'llvmpipe ([^)]*)' out/rigorous-gpu.txt | head -1 || echo 'the GPU'), the rigorous orders' table a 3-D texture):"
    echo
    echo "- rigorous orders: $(grep -i 'gpu time\|median' out/rigorous-gpu.txt | head -1)"
    echo "- scalar orders: $(grep -i 'gpu time\|median' out/rigorous-gpu-scalar.txt | head -1)"
    echo
    echo "Load when this page was written: $(nproc) CPU cores ($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)), load average $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$out"
echo "wrote $out"
