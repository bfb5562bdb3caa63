#!/usr/bin/env bash
# Screenshots of the five scenes with the gaze method: docs/screenshots/<scene>_gaze.png.
# Starts sph_server per scene on free loopback ports, lets it run, and has sph_viewer (headless,
# a hidden window under Xvfb) send a fixed gaze point and take the picture.
# Usage: docs/make_screenshots.sh [build-dir] [frames-per-scene]
set -euo pipefail
build=${1:-build}
frames=${2:-150}
root=$(cd "$(dirname "$0")/.." && pwd)
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24" "$0" "$@"
fi
mkdir -p "$root/docs/screenshots"
declare -A gaze=(  # where a person would look: at the water
  [dambreak]="0.35 0.62" [dambreak_obstacles]="0.35 0.62" [large_box]="0.5 0.62"
  [small_box]="0.5 0.6" [wave]="0.5 0.62")
for scene in dambreak dambreak_obstacles large_box small_box wave; do
  log=$(mktemp)
  "$build/bin/sph_server" --scene "$scene" --method gaze --frames-endpoint 'tcp://127.0.0.1:*' \
    --gaze-endpoint 'tcp://127.0.0.1:*' --pose-endpoint 'tcp://127.0.0.1:*' \
    --control-endpoint 'tcp://127.0.0.1:*' --status-interval 0 >"$log" 2>&1 &
  server=$!
  trap 'kill $server 2>/dev/null || true' EXIT
  for _ in $(seq 100); do grep -q "endpoint control" "$log" && break; sleep 0.1; done
  endpoint() { grep -o "endpoint $1 tcp://[0-9.:]*" "$log" | awk '{print $3}'; }
  out="$root/docs/screenshots/${scene}_gaze.png"
  # shellcheck disable=SC2086
  "$build/bin/sph_viewer" --frames-endpoint "$(endpoint frames)" --gaze-endpoint "$(endpoint gaze)" \
    --pose-endpoint "$(endpoint pose)" --control-endpoint "$(endpoint control)" \
    --gaze-at ${gaze[$scene]} --snapshot "$out" --frames "$frames" --timeout 120 --width 1280 --height 720
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -f "$log"
  echo "make_screenshots: $out"
done
