#!/usr/bin/env bash
# Extra time of the depth pass: scenes/ct-instrument.osgt with its opaque rod against the same
# scene without it (no opaque geometry: no depth copy, no depth texture, no ClipRay depth),
# side by side, alternating, ROUNDS times. Prints draw_ms medians (Markdown).
# Usage: tools/bench-depth-pass.sh [SIZE] [ROUNDS]   (default 512x512, 3; needs ../shared/data)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
size=${1:-512x512}
rounds=${2:-3}
volren="$here/build/bin/volren"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# The same scene without the Geode (the rod): the scene file's last child.
python3 - "$here/scenes/ct-instrument.osgt" "$work/without.osgt" <<'PY'
import sys
text = open(sys.argv[1]).read()
start = text.index('    osg::Geode {')
end = text.rindex('  }\n}')
text = text[:start] + text[end:]
text = text.replace('Children 3 {', 'Children 2 {', 1)
open(sys.argv[2], 'w').write(text)  # data names resolve along the data path
PY
median() { python3 -c "import json,sys; print('%.1f' % json.load(open(sys.argv[1]))['draw_ms_median'])" "$1"; }
echo "| round | with the rod (depth pass) ms | without opaque geometry ms |"
echo "|---:|---:|---:|"
for r in $(seq 1 "$rounds"); do
  "$volren" render "$here/scenes/ct-instrument.osgt" -o "$work/a.png" --size "$size" --frames 6 --stats "$work/a.json" \
    --eye 200,330,130 --center 0,0,0 > /dev/null
  "$volren" render "$work/without.osgt" -o "$work/b.png" --size "$size" --frames 6 --stats "$work/b.json" \
    --eye 200,330,130 --center 0,0,0 > /dev/null
  echo "| $r | $(median "$work/a.json") | $(median "$work/b.json") |"
done
