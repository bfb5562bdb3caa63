#!/usr/bin/env bash
# Viewer benchmark: render rate and frame-arrival-to-pixels time with N particles under Xvfb
# (Mesa llvmpipe, software GL). Usage: benchmarks/bench_viewer.sh [build-dir] [particles] [frames]
# Prints sph_viewer's --report line. Starts its own Xvfb when DISPLAY is unset.
set -euo pipefail
build=${1:-build}
particles=${2:-20000}
frames=${3:-600}
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24" "$0" "$@"
fi
out=$(mktemp)
"$build/bin/viewer_bench_publisher" --particles "$particles" --hz 60 >"$out" &
publisher=$!
trap 'kill $publisher 2>/dev/null || true; rm -f "$out"' EXIT
for _ in $(seq 50); do [ -s "$out" ] && break; sleep 0.1; done
endpoint=$(head -1 "$out")
echo "bench_viewer: $particles particles at 60 Hz from $endpoint, 1280x720, $(glxinfo -B 2>/dev/null | grep -m1 'renderer string' || echo 'software GL')"
"$build/bin/sph_viewer" --frames-endpoint "$endpoint" --frames "$frames" --timeout 120 --no-vsync \
  --width 1280 --height 720 --report --eye 0.5 0.8 1.8 --target 0.35 0.3 0.35
