#!/usr/bin/env bash
# The README's main command. Until sph_server, gaze_bridge and sph_viewer exist (issues 4-6), the
# main job is the headless bench: every shipped scene with the regular method, results in bench_out/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh
./build/bin/sph_bench --scene all --method regular --threads 2 --out bench_out "$@"
echo "results: $(pwd)/bench_out/<scene>/regular/{summary.json,frames.csv}"
