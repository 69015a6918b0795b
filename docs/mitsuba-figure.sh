#!/usr/bin/env bash
# Renders docs/images/mitsuba-sphere.png from the repository root: bash docs/mitsuba-figure.sh
# The Elaphe-like patch's BRDF, exported as a table (export --mitsuba), on a sphere in Mitsuba 3 (pip install mitsuba)
# under a small round light (1.4 degrees in radius) and a dim constant sky, 160 x 160 pixels, 64 samples per pixel,
# exposure 1000 on the relative BRDF (the diffracted orders are about 1e-3 of a mirror's peak). About 30 s on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/.."
mkdir -p docs/images out/mitsuba
python3 -c "import mitsuba" 2>/dev/null || { echo "docs/mitsuba-figure.sh: needs Mitsuba 3 (pip install mitsuba)" >&2; exit 2; }
echo "+ ./diffract export --synthetic elaphe-like --mitsuba out/mitsuba/elaphe-like.json" >&2
./diffract export --synthetic elaphe-like --mitsuba out/mitsuba/elaphe-like.json --quiet
echo "+ python3 python/mitsuba_sphere.py out/mitsuba/elaphe-like.json -o docs/images/mitsuba-sphere.png" >&2
python3 python/mitsuba_sphere.py out/mitsuba/elaphe-like.json -o docs/images/mitsuba-sphere.png
