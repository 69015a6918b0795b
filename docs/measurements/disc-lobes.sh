#!/usr/bin/env bash
# The lobes method under a disc light against the reference's exact disc (docs/measurements/filtering.md, section 9, "The lobes
# method under a disc"): runs DiscLobesTest's measurement (the blazed grating at a 10 um coherence length,
# 64 x 64 maps at theta_i = 30 degrees, 0.53, 2, 10 and 20-degree discs; the reference's disc takes minutes on 2 cores),
# GpuDiscLobesTest (GPU = CPU, the baked table), BakedDiscMeasurement (the baked table by its grid) and
# DiscLobesSpeedMeasurement (GL time of the lobes shader under the disc and under the Gaussian profile against FLSS,
# 64 x 64 maps at 65 um), and writes their measurements into docs/measurements/bench/disc-lobes.md. About 20 minutes on 2 cores,
# and an hour more for the reference's discs; from anywhere: bash docs/measurements/disc-lobes.sh (KEEP_CPU=1 runs the GPU parts
# alone and keeps DiscLobesTest's table and lines from the page as it is, for a change that leaves the CPU alone).
set -euo pipefail
cd "$(dirname "$0")/../.."
out=docs/measurements/bench/disc-lobes.md
rm -f target/test-reports/GpuDiscLobesTest.txt target/test-reports/DiscLobesSpeedMeasurement.txt \
    target/test-reports/BakedDiscMeasurement.txt
if [ -n "${KEEP_CPU:-}" ]; then
    # the page's DiscLobesTest part: its table rows and the lines of one row, as they are
    kept_rows=$(grep -E '^\| blazed \|' "$out")
    kept_lines=$(sed -n '/^Pixels of one row/,/^GPU against CPU/p' "$out" | grep '^- ')
    mvn -B -ntp -q test -Dtest=GpuDiscLobesTest
else
    rm -f target/test-reports/DiscLobesTest.txt
    mvn -B -ntp -q test -Dtest='DiscLobesTest#lobesFollowTheDiscWhereTheGaussianProfileDoesNot+lobesUnderADiscAreWithinOneOfTheReferencesDisc,GpuDiscLobesTest' \
        -Ddiffract.measure=disc-maps
    kept_rows=$(perl -ne 'print "| blazed | $1 um | $2 x $2, the 2 rows of the orders | $3 | $6 | $4 / $5 | $7 / $8 | $9 | $10 |\n"
        if /^blazed, (\d+) um, (\d+) px, ([\d.]+)-degree disc, 2 rows: lobes .*?lit: mean ([\d.]+), p95 ([\d.]+),.*? over (\d+) pixels.*?; the Gaussian profile .*?lit: mean ([\d.]+), p95 ([\d.]+),.*?; reference ([\d.]+) s, lobes ([\d.]+) s/' \
        target/test-reports/DiscLobesTest.txt)
    kept_lines=$(grep -E 'pixels of row' target/test-reports/DiscLobesTest.txt | sed 's/^/- /')
fi
mvn -B -ntp -q test -Dtest=BakedDiscMeasurement -Ddiffract.measure=baked-disc
# the GL times alone, after the CPU work, so that nothing else runs beside them
mvn -B -ntp -q test -Dtest=DiscLobesSpeedMeasurement -Ddiffract.measure=disc-speed
{
    echo "# The lobes method under a disc light"
    echo
    echo "Made by \`bash docs/measurements/disc-lobes.sh\` (\`DiscLobesTest\` with the long tests, \`GpuDiscLobesTest\`): CIEDE2000"
    echo "mean / p95 over the lit pixels at the reference's auto exposure; the lobes method under the disc and under the"
    echo "Gaussian profile of the same diameter, both against the reference's disc (\`DiscLightAverage\`)."
    echo
    echo "| patch | coherence | map | disc (deg) | lit px | lobes, disc | lobes, Gaussian profile | reference s | lobes s (CPU) |"
    echo "|---|---|---|---|---|---|---|---|---|"
    echo "$kept_rows"
    echo
    echo "Pixels of one row (the fast test):"
    echo
    echo "$kept_lines"
    echo
    echo "GPU against CPU, and the baked table against the CPU lobes method:"
    echo
    sed 's/^/- /' target/test-reports/GpuDiscLobesTest.txt
    echo
    echo "The baked table under a disc against the CPU lobes method, by its grid (\`BakedDiscMeasurement\`; the commands"
    echo "take 513 samples along u and v at 65 um and the automatic grid along w):"
    echo
    sed 's/^/- /' target/test-reports/BakedDiscMeasurement.txt
    echo
    echo "GL time per 64 x 64 map (llvmpipe; medians of alternating rounds):"
    echo
    sed 's/^/- /' target/test-reports/DiscLobesSpeedMeasurement.txt
    echo
    echo "$(nproc) CPU cores ($(sed -n 's/^model name\s*: //p' /proc/cpuinfo | head -1)), load average $(cut -d' ' -f1-3 /proc/loadavg)"
} >"$out"
# the baked table's means into docs/measurements/filtering.md's table (section 8), between its markers
python3 - target/test-reports/BakedDiscMeasurement.txt docs/measurements/filtering.md <<'PY'
import re, sys
lines, page = open(sys.argv[1]).read(), open(sys.argv[2]).read()
cells, grids = {}, {}
for patch, disc, theta, rest in re.findall(r"^(\S+), 65 um, \d+ px, ([\d.]+)-degree disc, theta_i (\d+): .*?lit mean / p95(.*)$",
                                          lines, re.M):
    for uv, w, mean in re.findall(r"; (\d+) x \d+ x (\d+): ([\d.]+) / [\d.]+", rest):
        cells.setdefault((patch, float(disc), uv), {})[theta] = mean
        grids[(patch, uv)] = w
names = {"elaphe-like": "Elaphe-like", "blazed-10um": "blazed-10um", "elaphe-scan": "elaphe-scan"}
columns = [(p, uv) for p in names for uv in ("257", "513") if (p, uv) in grids]
labels = [(f"{names[p]}, theta_i 0 / 30, " if i == 0 or columns[i - 1][0] != p else "") + f"{uv} x {uv} x {grids[(p, uv)]}"
          for i, (p, uv) in enumerate(columns)]
head = "| disc | " + " | ".join(labels) + " |"
rows = [head, "|---" * (len(columns) + 1) + "|"]
for disc in sorted({d for (_, d, _) in cells}):
    row = [f"{disc:g} degrees"]
    for p, uv in columns:
        c = cells.get((p, disc, uv), {})
        row.append(f"{c.get('0', '-')} / {c.get('30', '-')}")
    rows.append("| " + " | ".join(row) + " |")
table = "\n".join("  " + r for r in rows)
page, n = re.subn(r"(<!-- baked-disc table -->\n).*?(\n *<!-- end baked-disc table -->)",
                  lambda m: m.group(1) + table + m.group(2), page, flags=re.S)
if n != 1:
    sys.exit("docs/measurements/filtering.md: no baked-disc table between markers")
open(sys.argv[2], "w").write(page)
PY
cat "$out"
