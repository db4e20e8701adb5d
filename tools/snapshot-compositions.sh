#!/usr/bin/env bash
# What the renderer composes and draws, for comparing two versions of it (a refactor must not
# change either): every example scene's composed ray casters (`volren shader`) and image
# (`volren render`, float EXR), and the pairwise cover's sources and images
# (`volren permutations --pairwise --render --dump`).
# Usage: tools/snapshot-compositions.sh OUT_DIR [BUILD_DIR]
#        tools/snapshot-compositions.sh --compare BEFORE_DIR AFTER_DIR
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${1:-}" = "--compare" ]; then
  # Sources and raw images byte for byte; EXR files by their pixels (their headers may differ).
  before=$2 after=$3 build=${4:-"$here/build"}
  status=0 same=0
  for f in $(cd "$before" && find . -type f \( -name '*.frag' -o -name '*.rgba' -o -name '*.exr' \) | sort); do
    if [ ! -f "$after/$f" ]; then echo "missing: $f"; status=1; continue; fi
    case $f in
      *.exr) "$build/bin/volren" compare "$before/$f" "$after/$f" | grep -q "^max abs error:  0 " ;;
      *) cmp -s "$before/$f" "$after/$f" ;;
    esac && same=$((same + 1)) || { echo "differs: $f"; status=1; }
  done
  echo "snapshot: $same files identical"
  exit $status
fi
out=${1:?usage: tools/snapshot-compositions.sh OUT_DIR [BUILD_DIR]}
build=${2:-"$here/build"}
volren="$build/bin/volren"
mkdir -p "$out/scenes"
export MESA_SHADER_CACHE_DISABLE=true
for scene in "" "$here"/scenes/*.osgt; do
  name=$(basename "${scene:-default}" .osgt)
  "$volren" shader $scene > "$out/scenes/$name.frag"
  "$volren" render $scene -o "$out/scenes/$name.exr" --size 96x96 > /dev/null
done
"$volren" permutations --pairwise --render --dump "$out/pairwise" > "$out/pairwise.log"
tail -1 "$out/pairwise.log"
