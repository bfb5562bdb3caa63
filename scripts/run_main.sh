#!/usr/bin/env bash
# The README's main command: installs what is missing, builds the three programs it runs, then runs
# the whole system on this machine: sph_server, gaze_bridge and sph_viewer. The default gaze is the
# scene's own synthetic recording (scenes/<scene>.gaze.csv) replayed in real time and looped; name a
# tracker with --bridge to use real gaze. With a display the viewer opens a window and the run lasts
# until it is closed; without one it renders under Xvfb for --seconds of wall time and says where
# the picture is.
#
#   bash scripts/run_main.sh [--scene NAME] [--method regular|surface|gaze|hybrid|foveated]
#                            [--seconds S] [--bridge "ARGS"] [--out DIR]
#
#   --scene NAME     dambreak (default), basin, dambreak_obstacles, large_box, small_box, wave
#   --method M       foveated (default), regular, surface, gaze or hybrid
#   --seconds S      headless only: wall time before the picture is taken (default 20)
#   --bridge "ARGS"  gaze_bridge options instead of the recording, e.g.
#                    --bridge "--source gazepoint --gazepoint-host 192.168.1.20"
#   --out DIR        logs and the picture (default main_out)
#
# Exit codes: 0 the run worked; 1 a program failed, or the tracker named by --bridge never sent a
# sample; 2 usage error.
set -euo pipefail
cd "$(dirname "$0")/.."

usage_error() { echo "run_main: $1 (see bash scripts/run_main.sh --help)" >&2; exit 2; }
need_value() { [ $# -ge 2 ] && [ -n "$2" ] && [ "${2#--}" = "$2" ] || usage_error "$1 needs a value"; }

scene=dambreak
method=foveated
seconds=20
bridge_args=""
out_dir=main_out
while [ $# -gt 0 ]; do
  case "$1" in
    --scene) need_value "$@"; scene="$2"; shift 2 ;;
    --method) need_value "$@"; method="$2"; shift 2 ;;
    --seconds) need_value "$@"; seconds="$2"; shift 2 ;;
    # The value is a list of options itself, so it may start with "--".
    --bridge) [ $# -ge 2 ] && [ -n "$2" ] || usage_error "--bridge needs a value"; bridge_args="$2"; shift 2 ;;
    --out) need_value "$@"; out_dir="$2"; shift 2 ;;
    -h|--help) awk 'NR > 1 && /^#/ { sub(/^# ?/, ""); print; next } NR > 1 { exit }' "$0"; exit 0 ;;
    *) usage_error "unknown argument '$1'" ;;
  esac
done
case "$method" in regular|surface|gaze|hybrid|foveated) ;; *) usage_error "--method must be regular, surface, gaze, hybrid or foveated, not '$method'" ;; esac
[[ "$seconds" =~ ^[0-9]+$ ]] && [ "$seconds" -gt 0 ] || usage_error "--seconds must be a whole number of seconds above 0, not '$seconds'"
[ -f "scenes/$scene.json" ] || usage_error "--scene: no scene '$scene' (scenes: $(cd scenes && ls ./*.json | sed 's|^\./||; s|\.json$||' | tr '\n' ' '))"

named_tracker=0
if [ -z "$bridge_args" ]; then
  bridge_args="--source replay --replay scenes/$scene.gaze.csv"
else
  named_tracker=1
fi

bash scripts/install_deps.sh
bin=build/bin
if [ ! -x "$bin/sph_server" ] || [ ! -x "$bin/gaze_bridge" ] || [ ! -x "$bin/sph_viewer" ]; then
  # Measured on a fresh clone: docs/performance.md, "First build".
  echo "run_main: first build of sph_server, gaze_bridge and sph_viewer: 3 to 8 minutes on 2 cores (later runs rebuild only what changed)"
fi
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j "$(nproc)" --target sph_server gaze_bridge sph_viewer
mkdir -p "$out_dir"
out_dir="$(cd "$out_dir" && pwd)"  # absolute, for the messages below

server_pid=""
bridge_pid=""
stop_all() {
  for pid in $server_pid $bridge_pid; do kill -TERM "$pid" 2>/dev/null || true; done
}
trap stop_all EXIT INT TERM

# The server binds 127.0.0.1:5555-5558; the bridge and the viewer connect (either may start first).
# Passive OpenMP waiting: the viewer and the bridge share the cores, and spinning threads that
# wait for a descheduled partner cost the step more than they save.
OMP_WAIT_POLICY=passive "$bin/sph_server" --scene "$scene" --method "$method" --status-interval 5 >"$out_dir/server.log" 2>&1 &
server_pid=$!
# shellcheck disable=SC2086  # bridge_args is a list of options on purpose
"$bin/gaze_bridge" $bridge_args >"$out_dir/gaze_bridge.log" 2>&1 &
bridge_pid=$!
sleep 1
for pid in $server_pid $bridge_pid; do
  kill -0 "$pid" 2>/dev/null || { echo "run_main: a process failed to start; see $out_dir/*.log" >&2; tail -n 5 "$out_dir"/*.log >&2; exit 1; }
done
echo "run_main: sph_server ($scene, $method) and gaze_bridge running; logs in $out_dir/"

if [ -n "${DISPLAY:-}" ] || [ -n "${WAYLAND_DISPLAY:-}" ]; then
  echo "run_main: opening the viewer window (close it or press Esc to stop everything)"
  "$bin/sph_viewer" --report 2>&1 | tee "$out_dir/viewer.log"
else
  echo "run_main: no display: rendering headless under Xvfb for $seconds s of wall time"
  # Software GL renders on the cores the server steps on: two pictures a second show the run, and
  # the rest of the viewer's share goes to the simulation.
  # -noreset: a reset when the viewer disconnects signals xvfb-run in its clean-up, which then can
  # fail with exit code 5 after the viewer succeeded (seen in CI).
  xvfb-run -a -s "-screen 0 1280x720x24 -noreset" \
    "$bin/sph_viewer" --snapshot "$out_dir/viewer.png" --duration "$seconds" --max-fps 2 --report \
    >"$out_dir/viewer.log" 2>&1 || { echo "run_main: the viewer failed; see $out_dir/viewer.log" >&2; tail -n 20 "$out_dir/viewer.log" >&2; exit 1; }
  echo "run_main: picture of the last frame: $out_dir/viewer.png"
fi

# Stop both and collect the bridge's verdict: exit code 3 means a named tracker never sent a sample.
stop_all
bridge_status=0
wait "$bridge_pid" 2>/dev/null || bridge_status=$?
wait "$server_pid" 2>/dev/null || true
server_pid=""
bridge_pid=""
echo "run_main: the server's last status lines ($out_dir/server.log):"
grep -E "steps/s" "$out_dir/server.log" | tail -n 2 || true
if [ "$bridge_status" -eq 3 ] && [ "$named_tracker" -eq 1 ]; then
  echo "run_main: FAILED: the tracker named by --bridge never connected (no gaze reached the server); see $out_dir/gaze_bridge.log" >&2
  exit 1
fi
if [ "$bridge_status" -ne 0 ]; then
  echo "run_main: FAILED: gaze_bridge exited with $bridge_status; see $out_dir/gaze_bridge.log" >&2
  exit 1
fi
