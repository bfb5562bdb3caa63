#!/usr/bin/env bash
# `cmake --install` into a temporary prefix, moved elsewhere afterwards (a relocated tree must still
# find its scenes), then the programs run with the source tree out of reach (check_installed_tree.sh).
#   install_test.sh BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
build_dir=$1 source_dir=$2 version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/first" >"$work/install.log"
mv "$work/first" "$work/moved"
[ -x "$work/moved/bin/sph_server" ] || { echo "FAIL: nothing installed"; cat "$work/install.log"; exit 1; }
bash "$(dirname "$0")/check_installed_tree.sh" "$work/moved" "$source_dir" "$build_dir" "$version"
