#!/usr/bin/env bash
# Runs programs from an installed tree the way a machine that never saw the source would: the source
# and build trees hidden behind empty folders (a private mount namespace, where the system allows
# one), a bare environment, the working folder /. Checks --version of every program, that the
# default scene folder is the installed one, and a 5-frame sph_bench run.
#   check_installed_tree.sh PREFIX SOURCE_DIR BUILD_DIR VERSION
set -euo pipefail

if [ "${1:-}" = "--checks" ]; then  # the part that runs with the trees hidden
  prefix=$2 version=$3
  bin=$prefix/bin
  out=$(mktemp -d)
  [ "$("$bin/sph_server" --version)" = "sph_server $version" ] || { echo "FAIL: sph_server --version"; exit 1; }
  # The default --scene-dir shown by --help: the scenes installed beside the program.
  # (Read whole first: grep -q stops reading at its match, and a pipe closed early fails the run.)
  help=$("$bin/sph_server" --help)
  grep -q -- "--scene-dir TEXT=$prefix/share/gaze-adaptive-sph/scenes" <<<"$help" ||
    { echo "FAIL: the default scene folder is not the installed one:"; grep -- --scene-dir <<<"$help"; exit 1; }
  "$bin/sph_bench" --scene small_box --frames 5 --out "$out/bench" >"$out/report.txt" 2>"$out/log.txt" ||
    { echo "FAIL: sph_bench from the installed tree"; cat "$out/log.txt"; exit 1; }
  [ "$(wc -l <"$out/bench/frames.csv")" -eq 6 ] || { echo "FAIL: frames.csv is not a header and 5 rows"; exit 1; }
  grep -q "small_box/" "$out/report.txt" || { echo "FAIL: no report line"; exit 1; }
  for program in sph_bench sph_gaze_record sph_keygen sph_relay gaze_bridge sph_viewer sph_load; do
    [ "$("$bin/$program" --version)" = "$program $version" ] || { echo "FAIL: $program --version"; exit 1; }
  done
  [ -f "$prefix/share/gaze-adaptive-sph/proto/sph.proto" ] || { echo "FAIL: no sph.proto"; exit 1; }
  [ -f "$prefix/share/doc/gaze-adaptive-sph/README.md" ] || { echo "FAIL: no README"; exit 1; }
  [ -f "$prefix/share/doc/gaze-adaptive-sph/examples/systemd/sph-server.service" ] || { echo "FAIL: no systemd example"; exit 1; }
  rm -rf "$out"
  echo "installed tree OK: $prefix"
  exit 0
fi

prefix=$1 source_dir=$2 build_dir=$3 version=$4
# A copy of this script outside the trees it hides.
self=$(mktemp)
trap 'rm -f "$self"' EXIT
cp "$0" "$self"
clean_env=(env -i PATH=/usr/bin:/bin HOME=/tmp)
if unshare --mount --map-root-user true 2>/dev/null; then
  hide="mount -t tmpfs none '$source_dir' && { [ ! -d '$build_dir' ] || mount -t tmpfs none '$build_dir'; }"
  (cd / && "${clean_env[@]}" unshare --mount --map-root-user bash -c "$hide && bash '$self' --checks '$prefix' '$version'")
else
  echo "note: no mount namespace here; the tree was still installed away from the source and run from /"
  (cd / && "${clean_env[@]}" bash "$self" --checks "$prefix" "$version")
fi
