#!/usr/bin/env bash
# Frame time of the PixelLight thesis's four configurations on one scene, measured side by
# side in one run (rounds interleave the configurations so machine load affects all alike).
# Usage: tools/bench-compositions.sh [INPUT] [SIZE] [ROUNDS]   (defaults: default scene, 512x512, 2)
#   None:    ray setup only (traversal=null)
#   Minimum: nearest reconstruction, no classification, no shading
#   Medium:  the defaults (trilinear, 1D TF, central gradients, Blinn-Phong, the scene's lights)
#   Maximum: tricubic reconstruction, central-9 gradients, Cook-Torrance
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
input=${1:-}
size=${2:-512x512}
rounds=${3:-2}
names=(None Minimum Medium Maximum)
sets=("--set traversal=null"
      "--set reconstruction=nearest --set classification=null --set lighting=off"
      ""
      "--set reconstruction=tricubic --set gradient=central9 --set illumination=cooktorrance")
frames=(4 4 3 2)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for round in $(seq 1 "$rounds"); do
  for i in "${!names[@]}"; do
    # shellcheck disable=SC2086
    "$volren" render $input -o "$work/${names[$i]}.png" --size "$size" --frames "${frames[$i]}" \
      --stats "$work/${names[$i]}.$round.json" ${sets[$i]} >/dev/null
  done
done
python3 - "$work" "$rounds" "$size" "${names[@]}" <<'PY'
import json, statistics, sys
work, rounds, size, names = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4:]
rows = {}
for n in names:
    ms = []
    for r in range(1, rounds + 1):
        s = json.load(open(f"{work}/{n}.{r}.json"))
        ms += [f["draw_ms"] for f in s["frames"][1:]]  # frame 1 pays for compilation
    rows[n] = (statistics.median(ms), len(ms), s["composition_keys"][0])
print(f"| configuration | ms/frame ({size}, median) | frames | x Medium |")
print("|---|---:|---:|---:|")
for n in names:
    print(f"| {n} | {rows[n][0]:.1f} | {rows[n][1]} | {rows[n][0] / rows['Medium'][0]:.3f} |")
print()
print(f"context: {s['context']}")
for n in names:
    print(f"- {n}: `{rows[n][2]}`")
PY
