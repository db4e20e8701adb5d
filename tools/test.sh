#!/usr/bin/env bash
# Quick start 2: installs what is needed, builds, and runs the whole default test suite.
# Extra arguments go to ctest (e.g. -L render, -R Slab). Slow suites carry the label `slow`
# and run only with: tools/test.sh -L slow
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
"$here/tools/setup.sh"
jobs=$(nproc 2>/dev/null || echo 2)
if [ $# -eq 0 ]; then set -- -LE slow; fi
ctest --test-dir "$here/build" --output-on-failure -j "$jobs" "$@"
