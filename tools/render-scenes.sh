#!/usr/bin/env bash
# Renders every example scene in scenes/ to docs/images/scene-NAME.png, and the scenes of
# docs/scenes/ (known limitations) to docs/images/limitation-NAME.png: the README's pictures.
# Usage: tools/render-scenes.sh [SIZE]   (default 480x360; needs a build and ../shared/data)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
size=${1:-480x360}
volren="$here/build/bin/volren"
[ -x "$volren" ] || { echo "render-scenes: build first (tools/setup.sh)" >&2; exit 1; }
mkdir -p "$here/docs/images"
for scene in "$here"/scenes/*.osgt; do
  name=$(basename "$scene" .osgt)
  "$volren" render "$scene" -o "$here/docs/images/scene-$name.png" --size "$size" --background 0.08,0.08,0.1
done
for scene in "$here"/docs/scenes/*.osgt; do
  name=$(basename "$scene" .osgt)
  "$volren" render "$scene" -o "$here/docs/images/limitation-$name.png" --size "$size" --background 0.08,0.08,0.1
done
