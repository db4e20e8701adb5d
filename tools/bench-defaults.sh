#!/usr/bin/env bash
# Which defaults the speed/accuracy front chooses over every shared dataset (issue #38, point 7).
# Runs `volren bench` on each volume of ../shared/data (CTs, MRIs, microscopy stacks, each with
# its default scene: a headlight and the TF from its histogram) with the matrix's rows that
# could beat the default (those drawing the default's picture, or faster or more accurate at
# little cost), then summarises every configuration over the datasets: on how many it beats the
# default (`volren bench`'s rule: better on one axis beyond the run's noise, not worse beyond it
# on the other), on how many the default beats it, and the geometric means of its time and RMSE
# over the default's. A configuration that beats the default on most datasets and loses on none
# is where the default should move (the table says which).
# Usage: tools/bench-defaults.sh [SIZE (default 192)] [FRAMES (default 5)] [OUT (default bench-defaults)]
# Writes OUT/<dataset>/bench.{md,csv,json,png} and OUT/summary.md (also printed).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
data="${VOLREN_SHARED_DATA:-$here/../shared/data}"
size=${1:-192}
frames=${2:-5}
out=${3:-bench-defaults}
configs='default;samplerate=0.5;samplerate=1;earlyTermination=0.99;earlyTermination=1;macrocellSize=4;macrocellSize=16'
configs+=';lodByDistance=on;texturePrecision=native;texturePrecision=16bit;volumestorage=bricked'
configs+=';classification=premultiplied;gradient=forward;acceleration=adaptive;acceleration=null;jitter=null'
mkdir -p "$out"
inputs=(ct/bonsai.nii.gz ct/CT_AVM.nii.gz ct/headsq dicom/pancreas_ct_subset mri/ch2.nii.gz mri/BaselineVolume.nrrd
        mri/HeadMRVolume.mhd microscopy/xyz_8bit__chromosomes.tif microscopy/xyz_calibrated_16bit__golgi_bfa.tif
        microscopy/xyzc_16bit__dna_conf_wf.tif)
folders=()
for input in "${inputs[@]}"; do
  path="$data/$input"
  [ -e "$path" ] || { echo "bench-defaults: $path not found" >&2; exit 1; }
  name=$(basename "$input"); name=${name%%.*}
  echo "bench-defaults: $input ($(date +%H:%M:%S))" >&2
  "$volren" bench "$path" --size "${size}x${size}" --frames "$frames" --configs "$configs" --out "$out/$name" >/dev/null
  folders+=("$out/$name")
done
python3 - "$out/summary.md" "$size" "$frames" "${folders[@]}" <<'EOF'
import json, math, sys
summary, size, frames, folders = sys.argv[1], sys.argv[2], sys.argv[3], sys.argv[4:]
per = {}  # config -> list of (dataset, time ratio, rmse ratio, beats, beaten)
for folder in folders:
    rows = [r for r in json.load(open(folder + "/bench.json"))["rows"] if r["renderer"] == "volren"]
    default = next(r for r in rows if r["config"] == "default")
    for r in rows:
        if r["config"] == "default" or r["truth"] != default["truth"]:
            continue
        t, e = r["frame_ms"] / default["frame_ms"], r["rmse"] / default["rmse"] if default["rmse"] > 0 else 1.0
        per.setdefault(r["config"], []).append((r["dataset"], t, e, r["beats_default"], r["beaten_by_default"]))
lines = ["| configuration | datasets | beats the default on | the default beats it on | time x default (geometric mean, range) | RMSE x default (geometric mean, range) |",
         "|---|---:|---:|---:|---|---|"]
for config, entries in sorted(per.items(), key=lambda kv: -sum(x[3] for x in kv[1])):
    gm = lambda xs: math.exp(sum(math.log(max(x, 1e-12)) for x in xs) / len(xs))
    ts, es = [x[1] for x in entries], [x[2] for x in entries]
    beats = [x[0] for x in entries if x[3]]
    lines.append(f"| {config} | {len(entries)} | {len(beats)} | {sum(x[4] for x in entries)} | "
                 f"{gm(ts):.2f} ({min(ts):.2f}-{max(ts):.2f}) | {gm(es):.2f} ({min(es):.2f}-{max(es):.2f}) |")
    if beats:
        lines.append(f"|  | beats it on: {', '.join(beats)} | | | | |")
text = f"Over {len(folders)} shared datasets at {size}x{size}, {frames} frames each (tools/bench-defaults.sh):\n\n" + "\n".join(lines) + "\n"
open(summary, "w").write(text)
print(text)
EOF
