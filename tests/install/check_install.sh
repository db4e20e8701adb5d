#!/usr/bin/env bash
# Installs the build into a scratch prefix, builds tests/install/consumer against it with
# find_package(volren), and runs it on VOLUME. Usage: check_install.sh BUILD_DIR VOLUME
set -euo pipefail
build=$1
volume=$2
here=$(cd "$(dirname "$0")" && pwd)
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix/usr-local" >/dev/null
cmake -S "$here/consumer" -B "$prefix/consumer-build" -DCMAKE_PREFIX_PATH="$prefix/usr-local" >/dev/null
cmake --build "$prefix/consumer-build" >/dev/null
# Nothing from the build tree may leak in: the consumer only sees the install prefix.
VOLREN_SHARE_DIR= "$prefix/consumer-build/consumer" "$volume" | tee "$prefix/out.txt"
grep -q "share: $prefix/usr-local/share/volren" "$prefix/out.txt"
