#!/usr/bin/env bash
# Which defaults the speed/accuracy front chooses over every shared dataset (issue #38, point 7).
# Runs `volren bench` on each volume of ../shared/data (CTs, MRIs, microscopy stacks, each with
# its default scene: a headlight and the TF from its histogram) with the matrix's rows that
# could beat the default (those drawing the default's picture, or faster or more accurate at
# little cost), REPEATS times (the datasets in a different order each time), then summarises
# every configuration over the datasets: on how many it beats the default (`volren bench`'s
# rule: better on one axis beyond the run's noise, not worse beyond it on the other) in most of
# the repeats, on how many the default beats it so, and the geometric mean over the datasets of
# its median time over the default's (and of its RMSE over the default's). One row is the
# default under another name (`twin`: earlyTermination at its default value): what it "beats"
# and its time ratios are the noise of this machine between rows, which the bench's own margin
# (frame-to-frame deviation within a row) does not see.
# Usage: tools/bench-defaults.sh [SIZE (default 192)] [FRAMES (default 9)] [REPEATS (default 3)] [OUT (default bench-defaults)]
# Writes OUT/<dataset>/run<k>/bench.{md,csv,json} and OUT/summary.md (also printed).
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
volren="$here/build/bin/volren"
data="${VOLREN_SHARED_DATA:-$here/../shared/data}"
size=${1:-192}
frames=${2:-9}
repeats=${3:-3}
out=${4:-bench-defaults}
twin='earlyTermination=0.998046875'  # RenderSettings' default, 1 - 1/512
configs="default;$twin;samplerate=1;earlyTermination=0.99;earlyTermination=1;macrocellSize=4;macrocellSize=16"
configs+=';lodByDistance=on;texturePrecision=native;volumestorage=bricked;classification=premultiplied'
configs+=';acceleration=adaptive;acceleration=null;jitter=null'
mkdir -p "$out"
inputs=(ct/bonsai.nii.gz ct/CT_AVM.nii.gz ct/headsq/quarter.nhdr dicom/pancreas_ct_subset mri/ch2.nii.gz mri/BaselineVolume.nrrd
        mri/HeadMRVolume.mhd microscopy/xyz_8bit__chromosomes.tif microscopy/xyz_calibrated_16bit__golgi_bfa.tif
        microscopy/xyzc_16bit__dna_conf_wf.tif)
for input in "${inputs[@]}"; do
  [ -e "$data/$input" ] || { echo "bench-defaults: $data/$input not found" >&2; exit 1; }
done
for ((run = 1; run <= repeats; ++run)); do
  order=("${inputs[@]}")
  if ((run % 2 == 0)); then order=(); for ((i = ${#inputs[@]} - 1; i >= 0; --i)); do order+=("${inputs[i]}"); done; fi
  for input in "${order[@]}"; do
    name=$(basename "$input"); name=${name%%.*}
    echo "bench-defaults: run $run, $input ($(date +%H:%M:%S))" >&2
    "$volren" bench "$data/$input" --size "${size}x${size}" --frames "$frames" --configs "$configs" \
      --out "$out/$name/run$run" >/dev/null 2>"$out/$name-run$run.log"
  done
done
python3 - "$out" "$size" "$frames" "$repeats" "$twin" <<'EOF'
import glob, json, math, os, statistics, sys
out, size, frames, repeats, twin = sys.argv[1], sys.argv[2], sys.argv[3], int(sys.argv[4]), sys.argv[5]
per = {}  # config -> dataset -> list of (time ratio, rmse ratio, beats, beaten), one per run
for path in sorted(glob.glob(os.path.join(out, "*", "run*", "bench.json"))):
    rows = [r for r in json.load(open(path))["rows"] if r["renderer"] == "volren"]
    default = next(r for r in rows if r["config"] == "default")
    for r in rows:
        if r["config"] == "default" or r["truth"] != default["truth"]:
            continue
        e = r["rmse"] / default["rmse"] if default["rmse"] > 0 else 1.0
        per.setdefault(r["config"], {}).setdefault(r["dataset"], []).append(
            (r["frame_ms"] / default["frame_ms"], e, r["beats_default"], r["beaten_by_default"]))
gm = lambda xs: math.exp(sum(math.log(max(x, 1e-12)) for x in xs) / len(xs))
lines = ["| configuration | datasets | beats the default on (most runs) | the default beats it on | median time x default, geometric mean (range) | RMSE x default, geometric mean (range) |",
         "|---|---:|---:|---:|---|---|"]
def order(item):
    config, datasets = item
    return -sum(sum(x[2] for x in runs) * 2 > len(runs) for runs in datasets.values())
for config, datasets in sorted(per.items(), key=order):
    ts = [statistics.median(x[0] for x in runs) for runs in datasets.values()]
    es = [statistics.median(x[1] for x in runs) for runs in datasets.values()]
    beats = [d for d, runs in datasets.items() if sum(x[2] for x in runs) * 2 > len(runs)]
    beaten = [d for d, runs in datasets.items() if sum(x[3] for x in runs) * 2 > len(runs)]
    name = config + (" (the default: twin)" if config == twin else "")
    lines.append(f"| {name} | {len(datasets)} | {len(beats)} | {len(beaten)} | "
                 f"{gm(ts):.2f} ({min(ts):.2f}-{max(ts):.2f}) | {gm(es):.2f} ({min(es):.2f}-{max(es):.2f}) |")
    if beats:
        lines.append(f"|  | beats it on: {', '.join(beats)} | | | | |")
text = (f"Over {len(next(iter(per.values())))} shared datasets at {size}x{size}, {frames} frames a row, "
        f"{repeats} runs (tools/bench-defaults.sh):\n\n" + "\n".join(lines) + "\n")
open(os.path.join(out, "summary.md"), "w").write(text)
print(text)
EOF
