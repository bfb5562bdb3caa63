#!/usr/bin/env bash
# The README's main command: installs what is missing, builds, then runs the whole system on this
# machine: sph_server (a scene and method), gaze_bridge (synthetic gaze unless a tracker is named)
# and sph_viewer. The default gaze is the scene's own synthetic recording (scenes/<scene>.gaze.csv,
# made by the fixation/saccade model with targets on the water), replayed by the bridge in real
# time and looped; name a tracker with --bridge to use real gaze. With a display the viewer opens
# a window and the run lasts until it is closed; without one the viewer renders headless under
# Xvfb and the script says where the pictures are.
#
#   bash scripts/run_main.sh [--scene NAME] [--method regular|surface|gaze|hybrid]
#                            [--seconds S] [--bridge "ARGS"] [--out DIR]
#   e.g. --bridge "--source gazepoint --gazepoint-host 192.168.1.20"
set -euo pipefail
cd "$(dirname "$0")/.."

scene=dambreak
method=gaze
seconds=20          # headless only: how long to run before the snapshot
bridge_args=""      # default: replay the scene's synthetic gaze recording
out_dir=main_out
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) scene="$2"; shift 2 ;;
    --method) method="$2"; shift 2 ;;
    --seconds) seconds="$2"; shift 2 ;;
    --bridge) bridge_args="$2"; shift 2 ;;
    --out) out_dir="$2"; shift 2 ;;
    -h|--help) sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "run_main: unknown argument '$1' (try --help)" >&2; exit 2 ;;
  esac
done

[ -n "$bridge_args" ] || bridge_args="--source replay --replay scenes/$scene.gaze.csv"

bash scripts/install_deps.sh
bash scripts/build.sh
mkdir -p "$out_dir"
out_dir="$(cd "$out_dir" && pwd)"  # absolute, for the messages below
bin=build/bin

pids=()
cleanup() {
  for pid in "${pids[@]}"; do kill -TERM "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null || true; done
}
trap cleanup EXIT INT TERM

# The server binds 127.0.0.1:5555-5558; the bridge and the viewer connect (either may start first).
# Passive OpenMP waiting: the viewer and the bridge share the cores, and spinning threads that
# wait for a descheduled partner cost the step more than they save.
OMP_WAIT_POLICY=passive "$bin/sph_server" --scene "$scene" --method "$method" --status-interval 5 >"$out_dir/server.log" 2>&1 &
pids+=($!)
# shellcheck disable=SC2086  # bridge_args is a list of options on purpose
"$bin/gaze_bridge" $bridge_args >"$out_dir/gaze_bridge.log" 2>&1 &
pids+=($!)
sleep 1
for pid in "${pids[@]}"; do
  kill -0 "$pid" 2>/dev/null || { echo "run_main: a process failed to start; see $out_dir/*.log" >&2; tail -n 5 "$out_dir"/*.log >&2; exit 1; }
done
echo "run_main: sph_server ($scene, $method) and gaze_bridge running; logs in $out_dir/"

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  echo "run_main: opening the viewer window (close it or press Esc to stop everything)"
  "$bin/sph_viewer" --report | tee "$out_dir/viewer.log"
else
  # The viewer counts frames it has drawn; software GL under Xvfb draws 10-15 a second.
  frames=$((seconds * 8))
  echo "run_main: no display: rendering headless under Xvfb for about $seconds s"
  xvfb-run -a -s "-screen 0 1280x720x24" \
    "$bin/sph_viewer" --snapshot "$out_dir/viewer.png" --frames "$frames" --timeout $((seconds * 4 + 60)) --report \
    >"$out_dir/viewer.log" 2>&1 || { echo "run_main: the viewer failed; see $out_dir/viewer.log" >&2; tail -n 20 "$out_dir/viewer.log" >&2; exit 1; }
  echo "run_main: picture of the last frame: $out_dir/viewer.png"
fi
cleanup
pids=()
echo "run_main: the server's last status lines ($out_dir/server.log):"
grep -E "steps/s" "$out_dir/server.log" | tail -n 2 || true
