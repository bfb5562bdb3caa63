#!/usr/bin/env bash
# Screenshots of the five scenes with the gaze method: docs/screenshots/<scene>_fluid.png in fluid
# mode (the default render), and docs/screenshots/dambreak_particles.png, the dam break in particles
# mode from the same server, with the server's default preset (pbf); and the dam break under the
# foveated method with the real-time governor off (so the rings sit where the eye's acuity puts
# them): dambreak_foveated_rings.png in fluid mode with the rings and the panel's figures,
# dambreak_foveated_levels.png in particles mode with the level legend. Starts
# sph_server per scene on free loopback ports (with --neighbor-counts, so spray shows as
# droplets), and has sph_viewer (headless, a hidden window under Xvfb) send a fixed gaze point and
# take the picture at the first frame it draws at or after a chosen sim time (the server runs in
# real time). The fluid pictures use --fluid-scale 1
# (full resolution; the default on software GL is half).
# Usage: docs/make_screenshots.sh [build-dir [picture...]], a picture being a scene name or
# "foveated" (default: all).
set -euo pipefail
if [ -z "${DISPLAY:-}" ]; then
  exec xvfb-run -a -s "-screen 0 1920x1080x24 -noreset" "$0" "$@"
fi
build=${1:-build}
shift || true
wanted=("$@")
want() { [ ${#wanted[@]} -eq 0 ] || [[ " ${wanted[*]} " == *" $1 "* ]]; }
root=$(cd "$(dirname "$0")/.." && pwd)
mkdir -p "$root/docs/screenshots"
declare -A gaze=(  # where a person would look: at the water
  [dambreak]="0.35 0.62" [dambreak_obstacles]="0.35 0.62" [large_box]="0.5 0.62"
  [small_box]="0.5 0.6" [wave]="0.5 0.62")
declare -A moment=(  # sim seconds: the surge, the flow past the obstacles, the spreading sheet, waves
  [dambreak]=1.6 [dambreak_obstacles]=2.0 [large_box]=0.7 [small_box]=1.0 [wave]=3.0 [foveated]=2.0)
gaze[foveated]="0.6 0.6"  # on the water, where the rings have room
server=
trap '[ -n "$server" ] && kill $server 2>/dev/null || true' EXIT
for scene in dambreak dambreak_obstacles large_box small_box wave foveated; do
  want "$scene" || continue
  log=$(mktemp)
  if [ "$scene" = foveated ]; then
    method=(--scene dambreak --method foveated --realtime off)
  else
    method=(--scene "$scene" --method gaze)
  fi
  "$build/bin/sph_server" "${method[@]}" --neighbor-counts --frames-endpoint 'tcp://127.0.0.1:*' \
    --gaze-endpoint 'tcp://127.0.0.1:*' --pose-endpoint 'tcp://127.0.0.1:*' \
    --control-endpoint 'tcp://127.0.0.1:*' --status-interval 0 >"$log" 2>&1 &
  server=$!
  # pbf settles the water before the server binds: up to a few tens of seconds on 2 cores.
  for _ in $(seq 900); do grep -q "endpoint control" "$log" && break; sleep 0.1; done
  endpoint() { grep -o "endpoint $1 tcp://[0-9.:]*" "$log" | awk '{print $3}'; }
  shoot() {  # $1 output, then viewer options
    local out=$1
    shift
    # shellcheck disable=SC2086
    "$build/bin/sph_viewer" --frames-endpoint "$(endpoint frames)" --gaze-endpoint "$(endpoint gaze)" \
      --pose-endpoint "$(endpoint pose)" --control-endpoint "$(endpoint control)" --viewer-id "shot-$(basename "$out")" \
      --gaze-at ${gaze[$scene]} --snapshot "$out" --snapshot-at "${moment[$scene]}" --timeout 120 \
      --width 1280 --height 720 "$@"
    echo "make_screenshots: $out"
  }
  if [ "$scene" = foveated ]; then
    shoot "$root/docs/screenshots/dambreak_foveated_rings.png" --fluid-scale 1 &
    viewers=($!)
    shoot "$root/docs/screenshots/dambreak_foveated_levels.png" --render particles &
    viewers+=($!)
  else
    shoot "$root/docs/screenshots/${scene}_fluid.png" --fluid-scale 1 &
    viewers=($!)
  fi
  if [ "$scene" = dambreak ]; then
    # The particles picture beside the fluid one: the same server, the same chosen sim time.
    shoot "$root/docs/screenshots/dambreak_particles.png" --render particles &
    viewers+=($!)
  fi
  wait "${viewers[@]}"
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  server=
  rm -f "$log"
done
