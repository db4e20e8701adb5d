#!/usr/bin/env bash
# Empty-space skipping side by side: each shared CT with a dense TF (the default scene's, from
# the histogram), a sparse one (opacity only above the 99th percentile: bone, metal), an empty
# one (nothing visible), and MIP, MinIP and the isosurface with the dense TF, rendered with
# skipping (the default) and without it (--set acceleration=null), alternating, in one run. Prints the median draw time of each, the
# ratios, and the largest pixel difference between the two images (0 when skipping is exact).
# Usage: tools/bench-skipping.sh [SIZE (default 256)] [ROUNDS (default 3)]
# (VOLREN_BENCH_INPUTS and VOLREN_BENCH_KINDS pick datasets and rows, e.g. VOLREN_BENCH_KINDS="empty mip")
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
data="${VOLREN_SHARED_DATA:-$here/../shared/data}"
size=${1:-256}
rounds=${2:-3}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

median() { sort -g | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2] + v[NR/2+1]) / 2}'; }

printf '| dataset | TF or traversal | skipping ms | no skipping ms | ratio | max pixel difference |\n|---|---|---|---|---|---|\n'
for input in ${VOLREN_BENCH_INPUTS:-ct/bonsai.nii.gz ct/CT_AVM.nii.gz dicom/pancreas_ct_subset}; do
  path="$data/$input"
  [ -e "$path" ] || { echo "skipping $input: not found" >&2; continue; }
  info=$("$volren" info "$path")
  lo=$(sed -n 's/^value range: *\([^ ]*\) .. \([^ ]*\)$/\1/p' <<<"$info")
  hi=$(sed -n 's/^value range: *\([^ ]*\) .. \([^ ]*\)$/\2/p' <<<"$info")
  p99=$(sed -n 's/.*p99 \([^,]*\),.*/\1/p' <<<"$info")
  printf '%s 0 0 0 0\n%s 0 0 0 0\n%s 255 240 220 200\n' "$lo" "$p99" "$hi" >"$work/sparse.tf"
  printf '%s 0 0 0 0\n%s 0 0 0 0\n' "$lo" "$hi" >"$work/empty.tf"
  for kind in ${VOLREN_BENCH_KINDS:-dense sparse empty mip minip isosurface}; do
    args=()  # the sparse and empty TFs, or a traversal with the dense (default) TF
    case "$kind" in
      sparse | empty) args=(--tf "$work/$kind.tf") ;;
      mip) args=(--set traversal=mip --set acceleration=range) ;;  # MIP leaps only when asked
      minip | isosurface) args=(--set "traversal=$kind") ;;
    esac
    for r in $(seq "$rounds"); do
      for run in on off; do  # on: skipping (occupancy or range), off: acceleration=null (the later --set wins)
        skip=()
        [ "$run" = off ] && skip=(--set acceleration=null)
        "$volren" render "$path" -o "$work/$run.exr" --size "${size}x${size}" --frames 4 "${args[@]}" "${skip[@]}" \
          --stats "$work/$run.json" >/dev/null
        sed -n 's/.*"draw_ms_median": *\([0-9.e+-]*\).*/\1/p' "$work/$run.json" >>"$work/$run.ms"
      done
    done
    on=$(median <"$work/on.ms")
    off=$(median <"$work/off.ms")
    maxdiff=$("$volren" compare "$work/on.exr" "$work/off.exr" | sed -n 's/^max abs error: *\([^ ]*\).*/\1/p')
    printf '| %s | %s | %.1f | %.1f | %.3f | %s |\n' "$input" "$kind" "$on" "$off" "$(awk -v a="$on" -v b="$off" 'BEGIN {print a / b}')" "$maxdiff"
    rm -f "$work"/*.ms
  done
done
