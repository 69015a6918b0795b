#!/usr/bin/env bash
# Reruns the extremes matrix (tests/diffract/render/ExtremesReportTest.java) and writes
# docs/measurements/extremes.md from its two tables (target/extremes-threshold.md, target/extremes.md). Needs Xvfb + Mesa.
set -euo pipefail
cd "$(dirname "$0")/../.."
xvfb-run -a -s "-screen 0 1280x1024x24" mvn -B -ntp -q test -Dtest=ExtremesReportTest -Ddiffract.excludedGroups=none > /dev/null
{
cat <<'INTRO'
# Numerical stability at the extremes

Made by `bash docs/measurements/extremes.sh` (it runs `ExtremesReportTest`, which also fails if any map holds a NaN, an Inf or a
negative value, or if FLSS on the automatic expansion misses the reference by more than mean CIEDE2000 1 or 10 %
of the monochromatic peak).

## Where the thesis' float32 series fails, and the switch

Blazed gratings (period 2.5 um, 20 pixels of 0.125 um, 4 periods, 8 rows), monochromatic maps at 380 nm, light at
normal incidence, 24 x 24, coherence length 10 um, FLSS with a 7 x 7 window (it then equals the exact model up to
the expansion). Error: max |rho - rho_ref| / max rho_ref against the CPU reference. "Estimated plain error" is
`Float32Cancellation.plainSeriesError` of the patch's own terms at |w| = 2 (float32 rounding plus the truncated
tail); above 1e-3 the automatic expansion switches to the phase-centred one.

INTRO
cat target/extremes-threshold.md
cat <<'MATRIX'

The estimate switches one step early (at x = 11 the plain series errs by 1e-3 of the peak, at x = 12.6 by 7e-3,
and from x ~ 15 it is noise or overflows to NaN); the phase-centred path stays near 1e-5 at every height.

## The matrix

Cases: the gratings above with max|h| 0.01 to 2 um (x = 2 k max|h| = 0.3 to 66 at 380 nm), a flat (constant)
patch 5 x 7, a 1 x 1 patch, an odd non-square 21 x 5 grating; light at theta_i = 0, 60, 89.9 degrees in the x-z
plane (the 24 x 24 map's pixels reach theta_r = 80 degrees; theta_r = 89.9, the exact specular direction and
w -> 0 are point-tested by `ExtremesTest` (CPU) and `GpuFinitenessTest` (GPU)); N = 0 and N = 100 on the 0.5 um
grating; PQ's 1 - cos(omega T) -> 0 at integer lookups is `ExtremesTest.pqAtIntegerLookupsWhereOneMinusCosVanishes`.
The 4096 x 4096 patch has its own table below. Settings: 30 terms unless stated, 3 x 3 window, 5 nm steps, coherence length
10 um, PQ 3 replicas; reference at 1 nm with the full window.

Columns: "expansion" is what `--expansion auto` chose (centred: centres x orders per centre); errors against the
CPU reference, colour maps as mean CIEDE2000 over the unit disk (and over the lit pixels) after the reference's
automatic exposure, monochromatic maps as max |rho - rho_ref| / max rho_ref. "GPU error, plain series" is the
thesis' series around 0 on the GPU for the cases where the switch chose the centred one. NMM's and PQ's own errors
(NMM's nodes on a 10 um patch, PQ's sinc and replication) are the variants', not the extremes' (docs/measurements/accuracy.md).

MATRIX
cat target/extremes.md
cat <<'BIG'

## A 4096 x 4096 patch

A blazed grating 0.02 um high, period 0.8 um (16 pixels of 0.05 um), 256 periods, 4096 rows (204.8 um square),
N = 4, thesis coherence length (sigma_f = 2 texels, so a 25 x 25 window): 5 layers of 128 MiB on the GPU. Its
reference (16 complex double transforms of 4096^2 per centre) does not fit, but its heights vary along x only, so
in the plane of incidence (the middle row of a 33 x 33 monochromatic map, light at phi_i = 0) its P is that of its
single row, whose reference is cheap. Error: max |rho - rho_ref| / max rho_ref along that row. Every pixel of the
GPU maps is finite and non-negative.

BIG
cat target/extremes-4096.md
echo
echo "GL: $(cat target/extremes-renderer.txt) (llvmpipe runs the shaders on the CPU, in float32 as a GPU does)."
} > docs/measurements/extremes.md
echo "wrote docs/measurements/extremes.md"
