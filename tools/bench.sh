#!/usr/bin/env bash
# The speed-against-accuracy benchmark shown in the README: installs what it needs (gnuplot,
# python3-vtk9 for the VTK peer), builds, and runs `volren bench` on the default dataset with
# VTK's GPU ray caster beside it. Writes docs/bench/bench.{md,csv,json,png}.
# Usage: tools/bench.sh [volren bench options, e.g. --size 512x512 --frames 9 INPUT ...]
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
VOLREN_SETUP_BENCH=1 "$here/tools/setup.sh"
cd "$here"
exec build/bin/volren bench --size 256x256 --frames 5 --vtk --out docs/bench "$@"
