#!/usr/bin/env bash
# Regenerates docs/measurements/bench/local-window.md and docs/images/local-window.png, the measurements of docs/measurements/scans.md's
# close-ups (the window under each surface point), from the repository root: bash docs/measurements/local-window.sh
# The 52 um elaphe-scan on a plane, FLSS: the viewer's GPU ms per frame of a close-up under the local window against
# the same view under the averaged window (LocalWindowMeasurement, a few minutes on llvmpipe), the picture of both,
# and the numbers of LocalWindowSceneTest (the close-up's spread of colours, the convergence to the averaged window).
set -euo pipefail
cd "$(dirname "$0")/../.."
mvn -B -ntp -q test -Dtest='LocalWindowMeasurement,LocalWindowSceneTest' -Ddiffract.measure=glints
mkdir -p docs/measurements/bench docs/images
{
    cat target/local-window/local-window.md
    echo
    echo "\`LocalWindowSceneTest\` (48 x 48 pixels, the same scene; target/test-reports/LocalWindowSceneTest.txt):"
    echo
    sed 's/^/- /' target/test-reports/LocalWindowSceneTest.txt
} > docs/measurements/bench/local-window.md
cp target/local-window/local-window.png docs/images/local-window.png
