#!/usr/bin/env bash
# The Acceleration rows of `volren bench` on the shared CTs (bonsai, CT_AVM, the pancreas DICOM)
# with their dense default TF and a sparse one (opacity only above the 99th percentile: bone,
# metal, the pot), lit by the default headlight: skipping off, adaptive sampling, levels of
# detail, termination off and 8-bit textures against the default, each with its error against
# the reference of the same view. Writes one bench folder per dataset and TF under OUT
# (default bench-acceleration) and prints their tables.
# Usage: tools/bench-acceleration.sh [SIZE (default 256)] [FRAMES (default 5)] [OUT]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
data="${VOLREN_SHARED_DATA:-$here/../shared/data}"
size=${1:-256}
frames=${2:-5}
out=${3:-bench-acceleration}
configs='default;acceleration=null;acceleration=adaptive;acceleration=adaptive+adaptiveSteps=8;acceleration=adaptive+adaptiveTolerance=0.02;lod=1;lod=2;lodByDistance=on;earlyTermination=1;texturePrecision=native'
mkdir -p "$out"
for input in ct/bonsai.nii.gz ct/CT_AVM.nii.gz dicom/pancreas_ct_subset; do
  path="$data/$input"
  [ -e "$path" ] || { echo "skipping $input: not found" >&2; continue; }
  name=$(basename "$input" .nii.gz)
  info=$("$volren" info "$path")
  lo=$(sed -n 's/^value range: *\([^ ]*\) .. \([^ ]*\)$/\1/p' <<<"$info")
  hi=$(sed -n 's/^value range: *\([^ ]*\) .. \([^ ]*\)$/\2/p' <<<"$info")
  p99=$(sed -n 's/.*p99 \([^,]*\),.*/\1/p' <<<"$info")
  printf '%s 0 0 0 0\n%s 0 0 0 0\n%s 255 240 220 200\n' "$lo" "$p99" "$hi" >"$out/$name-sparse.tf"
  for tf in dense sparse; do
    tfarg=()
    [ "$tf" = sparse ] && tfarg=(--tf "$out/$name-sparse.tf")
    "$volren" bench "$path" "${tfarg[@]}" --size "${size}x${size}" --frames "$frames" --configs "$configs" \
      --out "$out/$name-$tf" >/dev/null
    echo "## $input, $tf TF"
    echo
    cat "$out/$name-$tf/bench.md"
    echo
  done
done
