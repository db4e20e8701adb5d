#!/usr/bin/env bash
# Quick start 1: installs what is needed, builds the program (and what it loads, no test), and
# renders the default scene to volren.png.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh" --target volren
"$here/build/bin/volren" "$@"
