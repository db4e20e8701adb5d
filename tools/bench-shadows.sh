#!/usr/bin/env bash
# Shadowing methods side by side on one dataset (default: the shared bonsai at 1200x900, the
# table shape of the system volren's light volume and cones come from): local shading, without
# early ray termination, adaptive sampling, the light volume at half and full resolution, cone
# shadows, cone shadows + ambient occlusion, shadow rays. One `volren render --stats` per row,
# back to back; prints each row's median draw time, its ratio to local shading, and its built
# volume (size, last build time, bytes per voxel of the volume).
# Usage: tools/bench-shadows.sh [DATASET] [SIZE (default 1200x900)] [FRAMES (default 4, at least 2; shadow rays take 2)]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
data="${VOLREN_SHARED_DATA:-$here/../shared/data}"
dataset=${1:-$data/ct/bonsai.nii.gz}
size=${2:-1200x900}
frames=${3:-4}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
rows=("local|" "no early termination|--set earlyTermination=1" "adaptive|--set acceleration=adaptive"
      "light volume|--set shadowing=light_volume" "light volume, full resolution|--set shadowing=light_volume --set lightVolumeScale=1"
      "cone shadows|--set shadowing=cone" "cone shadows + AO|--set shadowing=cone_ao" "shadow rays|--set shadowing=ray")
printf '| row | frame ms | ratio to local | built volume | build ms | bytes per voxel |\n|---|---:|---:|---|---:|---:|\n'
local_ms=""
for row in "${rows[@]}"; do
    name=${row%%|*}
    read -r -a args <<< "${row#*|}"
    n=$frames
    [[ $name == "shadow rays" ]] && n=2  # the second frame: the first compiles and uploads
    "$volren" render "$dataset" --size "$size" --frames "$n" "${args[@]}" --stats "$work/s.json" -o "$work/out.png" > /dev/null
    python3 - "$work/s.json" "$name" "${local_ms:-0}" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); name = sys.argv[2]; local = float(sys.argv[3])
ms = s["draw_ms_median"]; ratio = ms / local if local > 0 else 1.0
built = s.get("built_volumes", [])
if built:
    b = built[0]
    print("| %s | %.0f | %.2f | %s %dx%dx%d | %.0f | %.2f |" % (name, ms, ratio, b["kind"], *b["dims"], b["last_build_ms"], b["bytes_per_voxel"]))
else:
    print("| %s | %.0f | %.2f | | | |" % (name, ms, ratio))
PY
    if [[ -z $local_ms ]]; then  # the first row is the one the others are compared with
        local_ms=$(python3 -c "import json;print(json.load(open('$work/s.json'))['draw_ms_median'])")
    fi
done
