#!/usr/bin/env bash
# Viewer benchmark: render rate and frame-arrival-to-pixels time with N particles under Xvfb
# (Mesa llvmpipe, software GL), for each render mode in turn.
# Usage: benchmarks/bench_viewer.sh [build-dir] [particles] [frames] [rounds]
# Prints sph_viewer's --report line per mode, the modes alternating `rounds` times (a shared machine
# changes speed over a run: alternating keeps the comparison fair), then the fluid / particles ratio
# of the mean render rates. Extra viewer options come from $VIEWER_ARGS (e.g. "--fluid-scale 1").
# Starts its own Xvfb when DISPLAY is unset.
set -euo pipefail
build=${1:-build}
particles=${2:-20000}
frames=${3:-600}
rounds=${4:-1}
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$0" "$@"
fi
out=$(mktemp)
"$build/bin/viewer_bench_publisher" --particles "$particles" --hz 60 >"$out" &
publisher=$!
trap 'kill $publisher 2>/dev/null || true; rm -f "$out"' EXIT
for _ in $(seq 50); do [ -s "$out" ] && break; sleep 0.1; done
endpoint=$(head -1 "$out")
echo "bench_viewer: $particles particles at 60 Hz from $endpoint, 1280x720, $(glxinfo -B 2>/dev/null | grep -m1 'renderer string' || echo 'software GL')"
declare -A sum=([particles]=0 [fluid]=0)
for _ in $(seq "$rounds"); do
  for mode in particles fluid; do
    # shellcheck disable=SC2086
    line=$("$build/bin/sph_viewer" --frames-endpoint "$endpoint" --frames "$frames" --timeout 300 --no-vsync \
      --width 1280 --height 720 --report --render "$mode" --eye 0.5 0.8 1.8 --target 0.35 0.3 0.35 \
      ${VIEWER_ARGS:-} 2>&1 | grep 'sph_viewer report')
    echo "$mode: $line"
    fps=$(sed -n 's/.*render_fps=\([0-9.]*\).*/\1/p' <<<"$line")
    sum[$mode]=$(awk -v a="${sum[$mode]}" -v b="$fps" 'BEGIN { print a + b }')
  done
done
awk -v p="${sum[particles]}" -v f="${sum[fluid]}" -v n="$rounds" \
  'BEGIN { printf "bench_viewer: mean render_fps particles %.1f, fluid %.1f, fluid / particles %.2f\n", p / n, f / n, f / p }'
