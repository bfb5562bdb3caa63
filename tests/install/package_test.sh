#!/usr/bin/env bash
# The Debian package, built from the existing build tree (cpack): dpkg-deb -I names its
# dependencies; unpacked with dpkg-deb -x into an empty folder, its programs run from there with the
# source tree out of reach (check_installed_tree.sh).
#   package_test.sh BUILD_DIR SOURCE_DIR VERSION
set -euo pipefail
build_dir=$1 source_dir=$2 version=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cpack -G DEB --config "$build_dir/CPackConfig.cmake" -B "$work/pkg" >"$work/cpack.log" 2>&1 ||
  { echo "FAIL: cpack"; cat "$work/cpack.log"; exit 1; }
deb=$(ls "$work"/pkg/gaze-adaptive-sph_"$version"_amd64.deb)
info=$(dpkg-deb -I "$deb")
echo "$info" | grep -E "^ (Package|Version|Depends|Installed-Size):"
depends=$(echo "$info" | sed -n 's/^ Depends: //p')
for dependency in libzmq5 libstdc++6 libgomp1 python3-zmq python3-protobuf; do
  echo "$depends" | grep -q "$dependency" || { echo "FAIL: Depends lacks $dependency: $depends"; exit 1; }
done
mkdir "$work/root"
dpkg-deb -x "$deb" "$work/root"
bash "$(dirname "$0")/check_installed_tree.sh" "$work/root/usr" "$source_dir" "$build_dir" "$version"
