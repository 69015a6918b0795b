#!/usr/bin/env bash
# Renders one picture of each default scene (assets/scenes/*.json) into docs/images/scene-NAME.png, at the
# scene's own size, with the same `render` the tests use. Needs OpenGL 3.3; no display (headless EGL).
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
cd "$ROOT"
for scene in snake-elaphe snake-xenopeltis blazed-grating-plane brdfmap-elaphe; do
    ./diffract render "assets/scenes/$scene.json" -o "docs/images/scene-$scene.png"
done
