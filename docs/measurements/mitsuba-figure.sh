#!/usr/bin/env bash
# Renders docs/images/mitsuba-sphere.png and, beside it, docs/images/mitsuba-sphere-diffract.png from the repository
# root: bash docs/measurements/mitsuba-figure.sh
# The Elaphe-like patch's BRDF, exported as a table (export --mitsuba), on a sphere in Mitsuba 3 (pip install mitsuba)
# under a small round light (1.4 degrees in radius) and a dim constant sky, 160 x 160 pixels, 256 samples per pixel,
# exposure 1000 on the relative BRDF (the diffracted orders are about 1e-3 of a mirror's peak); then the same sphere,
# camera, light and exposure drawn by diffract's own renderer (the lobes method, its light a Gaussian of the same
# diameter, no sky). About 3 minutes on 2 cores.
set -euo pipefail
cd "$(dirname "$0")/../.."
mkdir -p docs/images out/mitsuba
python3 -c "import mitsuba" 2>/dev/null || { echo "docs/measurements/mitsuba-figure.sh: needs Mitsuba 3 (pip install mitsuba)" >&2; exit 2; }
echo "+ ./diffract export --synthetic elaphe-like --mitsuba out/mitsuba/elaphe-like.json" >&2
./diffract export --synthetic elaphe-like --mitsuba out/mitsuba/elaphe-like.json --quiet
echo "+ python3 python/mitsuba_sphere.py out/mitsuba/elaphe-like.json -o docs/images/mitsuba-sphere.png" >&2
python3 python/mitsuba_sphere.py out/mitsuba/elaphe-like.json -o docs/images/mitsuba-sphere.png
cat > out/mitsuba/sphere.json <<'SCENE'
{
  "image": {"width": 160, "height": 160},
  "camera": {"eye": [0, 0, 4.2], "lookAt": [0, 0, 0], "up": [0, 1, 0], "fieldOfViewDeg": 30},
  "light": {"direction": [9, 12, 13.2], "angularDiameterDeg": 2.8},
  "shape": {"kind": "sphere", "tangents": {"project": [1, 0, 0]}},
  "material": {"patch": {"procedural": "elaphe-like"}, "variant": "lobes", "normalisation": "energy",
               "exposure": EXPOSURE, "diffuseWeight": 0}
}
SCENE
sed -i "s/EXPOSURE/${DIFFRACT_EXPOSURE:-1000}/" out/mitsuba/sphere.json
echo "+ ./diffract render out/mitsuba/sphere.json -o docs/images/mitsuba-sphere-diffract.png" >&2
./diffract render out/mitsuba/sphere.json -o docs/images/mitsuba-sphere-diffract.png --quiet
