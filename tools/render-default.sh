#!/usr/bin/env bash
# Quick start 1: installs what is needed, builds, and renders the default scene to volren.png.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh"
"$here/build/bin/volren" "$@"
