#!/usr/bin/env bash
# What each added channel costs (issue 20): a synthetic 4-channel fluorescence stack
# (tools/make-channels-volume.py, SIZE^3, made once into the work folder) rendered with 1, 2, 3
# and 4 channels shown (`--set channels=...`), all in one ray, side by side in one `volren bench`
# run (frame time and RMSE against the reference per row); prints each row's frame time, its
# ratio to one channel and the cost of each added channel relative to the first. MODE blends the
# channels as `--set traversal=MODE` says (composite, additive, mip; default composite).
# Usage: tools/bench-channels.sh [SIZE (default 96)] [IMAGE (default 256x256)] [FRAMES (default 5)] [OUT (default a temp folder)] [MODE]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
size=${1:-96}
image=${2:-256x256}
frames=${3:-5}
out=${4:-$(mktemp -d)}
mode=${5:-composite}
mkdir -p "$out"
stack="$out/channels-$size.nrrd"
[[ -f $stack ]] || python3 "$here/tools/make-channels-volume.py" "$stack" 4 "$size"
"$volren" bench "$stack" --size "$image" --frames "$frames" --out "$out" \
    --configs "channels=0+traversal=$mode;channels=0,1+traversal=$mode;channels=0,1,2+traversal=$mode;channels=0,1,2,3+traversal=$mode" \
    > "$out/bench.log"
python3 - "$out/bench.json" <<'PY'
import json, sys
rows = json.load(open(sys.argv[1]))["rows"]
first = None
print("| channels shown | frame ms | ratio to one | each added channel / first | RMSE |\n|---|---:|---:|---:|---:|")
for r in rows:
    ms = r["frame_ms"]
    n = r["config"].split("+")[0].count(",") + 1
    first = first or ms
    added = (ms - first) / (n - 1) / first if n > 1 else 0.0
    print("| %d | %.1f | %.2f | %s | %.4f |" % (n, ms, ms / first, "%.2f" % added if n > 1 else "", r["rmse"]))
PY
