#!/usr/bin/env bash
# Screenshots of the real viewer (docs/images/viewer.png, the GL view, and docs/images/viewer-frame.png, the whole
# frame): `diffract view` opens its frame on a private Xvfb screen, draws, and once the picture is refined and the
# BRDF-map inset drawn saves what the view shows (glReadPixels, as the S key does) and what the screen shows of the
# frame.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
./diffract warm-up >/dev/null 2>&1 || true   # builds the jar when sources changed
shots="$(mktemp -d)"
trap 'rm -rf "$shots"' EXIT
# DISPLAY is set by xvfb-run here, so the launcher does not start (or flag) a second, private Xvfb
xvfb-run -a -s "-screen 0 1280x1024x24" ./diffract view --synthetic elaphe-like --shape sphere --theta-i 30 --phi-i 90 \
    --elevation 25 --azimuth -20 --size 520x460 --screenshot-dir "$shots" --screenshot-when-refined >/dev/null
mkdir -p docs/images
mv "$(ls "$shots"/diffract-viewer-*.png | head -1)" docs/images/viewer.png
mv "$shots/diffract-frame.png" docs/images/viewer-frame.png
echo "$ROOT/docs/images/viewer.png $ROOT/docs/images/viewer-frame.png"
