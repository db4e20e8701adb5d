#!/usr/bin/env bash
# Resident memory of the rendered composition sweep against the number of compositions rendered:
# it must stay flat (programs no volume uses are released) and below 500 MB at any count.
# Usage: tools/bench-sweep-memory.sh [COUNT] [BUILD_DIR] [volren permutations options, e.g. --no-check]
#        (default 4000 compositions)
# Prints one line per 500 compositions and the peak; exits 1 when the peak passes 500 MB or the
# last reading exceeds the first by more than 10%.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
count=${1:-4000}
build=${2:-"$here/build"}
shift $(($# < 2 ? $# : 2))
stats=$(mktemp --suffix=.json)
# Every 37th composition of the space, so the run mixes all kinds of composition.
MESA_SHADER_CACHE_DISABLE=true GALLIVM_PERF=nopt \
  LP_NUM_THREADS=0 LP_NATIVE_VECTOR_WIDTH=128 "$build/bin/volren" permutations --render --shard 5/37 --count "$count" --stats "$stats" "$@" > /dev/null
python3 - "$stats" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
rows = s["resident"]
for r in rows:
    print(f"{r['done']:>7} compositions rendered: resident {r['resident_mb']:7.1f} MB")
peak = s["peak_resident_mb"]
growth = rows[-1]["resident_mb"] / rows[0]["resident_mb"] - 1 if rows else 0
print(f"peak resident {peak:.1f} MB; growth from the first reading to the last {100 * growth:+.1f}%; "
      f"failures {s['failures']}; median {s['median_ms']:.0f} ms per composition")
sys.exit(0 if peak < 500 and growth < 0.10 and s["failures"] == 0 else 1)
PY
