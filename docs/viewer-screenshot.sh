#!/usr/bin/env bash
# Screenshot of the real viewer window (docs/images/viewer.png): `diffract view` opens its window on a private
# Xvfb screen, draws, and saves what the window shows (glReadPixels, as the S key does) once the picture is refined.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
./diffract warm-up >/dev/null 2>&1 || true   # builds the jar when sources changed
shots="$(mktemp -d)"
trap 'rm -rf "$shots"' EXIT
# DISPLAY is set by xvfb-run here, so the launcher does not start (or flag) a second, private Xvfb
xvfb-run -a -s "-screen 0 1280x1024x24" ./diffract view --synthetic elaphe-like --shape sphere --theta-i 30 --phi-i 90 \
    --elevation 25 --azimuth -20 --size 480x360 --screenshot-dir "$shots" --screenshot-when-refined >/dev/null
mkdir -p docs/images
mv "$(ls "$shots"/*.png | head -1)" docs/images/viewer.png
echo "$ROOT/docs/images/viewer.png"
