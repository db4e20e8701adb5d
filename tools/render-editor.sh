#!/usr/bin/env bash
# The README's picture of `volren view` with the transfer-function editor open, made headlessly:
# volren view at its default size on a virtual X display (Xvfb), 5 frames, the window saved to a file.
# Usage: tools/render-editor.sh [INPUT] [OUT.png]   (default: the Colin27 MRI head)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
input=${1:-"$here/../shared/data/mri/ch2.nii.gz"}
out=${2:-"$here/docs/images/volren-view-editor.png"}
"$here/tools/setup.sh" >/dev/null
xvfb-run -a -s "-screen 0 1680x1050x24" "$here/build/bin/volren" view "$input" --frames 5 --screenshot "$out"
