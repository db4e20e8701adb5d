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
# A closer view where the default framing (the scene's bounding sphere) leaves much empty space.
view() {
  case "$1" in
    ct-instrument) echo "--eye 200,330,130 --center 0,0,0" ;;
    two-volumes) echo "--eye 420,800,380 --center 0,0,-10" ;;
    isosurface-mesh) echo "--eye 250,420,190 --center 0,0,10" ;;
    *) echo "" ;;
  esac
}
for scene in "$here"/scenes/*.osgt; do
  name=$(basename "$scene" .osgt)
  # shellcheck disable=SC2046
  "$volren" render "$scene" -o "$here/docs/images/scene-$name.png" --size "$size" --background 0.08,0.08,0.1 $(view "$name")
done
for scene in "$here"/docs/scenes/*.osgt; do
  name=$(basename "$scene" .osgt)
  "$volren" render "$scene" -o "$here/docs/images/limitation-$name.png" --size "$size" --background 0.08,0.08,0.1
done
