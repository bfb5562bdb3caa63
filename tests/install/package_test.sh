#!/usr/bin/env bash
# The Debian package, built from the existing build tree (cpack): lintian finds no error or
# warning in it, every program has a manual page, dpkg-deb -I names its dependencies; unpacked with dpkg-deb -x into an empty folder, its programs run from there with the
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
# Debian's own checks of a package: no error and no warning (the informational tags left, hardening
# flags the build does not set, are docs/design.md's "Packaging").
command -v lintian >/dev/null || { echo "FAIL: lintian is not installed (bash scripts/install_deps.sh)"; exit 1; }
lintian --fail-on error,warning "$deb" >"$work/lintian.log" 2>&1 ||
  { echo "FAIL: lintian"; grep -v "running with root privileges" "$work/lintian.log"; exit 1; }
# A manual page for every program (the listing read whole: grep -q would close the pipe early).
contents=$(dpkg-deb -c "$deb")
for program in $(sed -n 's#.*\./usr/bin/##p' <<<"$contents"); do
  grep -q "usr/share/man/man1/$program.1.gz" <<<"$contents" || { echo "FAIL: no manual page for $program"; exit 1; }
done
mkdir "$work/root"
dpkg-deb -x "$deb" "$work/root"
bash "$(dirname "$0")/check_installed_tree.sh" "$work/root/usr" "$source_dir" "$build_dir" "$version"
