#!/usr/bin/env bash
# Plots a sph_bench matrix (the thesis's figures 5.1-5.11): for every scene folder under OUT_DIR
# with <method>/frames.csv inside, writes <scene>/steps_per_second.png and <scene>/particles.png,
# one line per method. Uses gnuplot (Debian gnuplot-nox, installed by scripts/install_deps.sh).
#   usage: scripts/plot_bench.sh [OUT_DIR]   (default bench_out)
set -euo pipefail
out_dir="${1:-bench_out}"
command -v gnuplot >/dev/null || { echo "plot_bench: gnuplot missing (run scripts/install_deps.sh)" >&2; exit 1; }
[ -d "$out_dir" ] || { echo "plot_bench: no folder '$out_dir'" >&2; exit 1; }

plotted=0
for scene_dir in "$out_dir"/*/; do
  scene="$(basename "$scene_dir")"
  methods=()
  for m in regular surface gaze hybrid; do
    [ -f "$scene_dir/$m/frames.csv" ] && methods+=("$m")
  done
  [ ${#methods[@]} -gt 0 ] || continue
  fps_plot=""
  count_plot=""
  for m in "${methods[@]}"; do
    csv="$scene_dir/$m/frames.csv"
    # Columns: 1 frame, 3 n_large, 4 n_small, 10 steps_per_s (see bench_output.cpp).
    fps_plot+="${fps_plot:+, }'$csv' using 1:10 with lines lw 1.5 title '$m'"
    count_plot+="${count_plot:+, }'$csv' using 1:(\$3+\$4) with lines lw 2 title '$m total'"
    count_plot+=", '$csv' using 1:4 with lines lw 1 dt 2 title '$m SMALL'"
  done
  gnuplot <<GNUPLOT
set datafile separator ','
set key outside right top
set grid
set terminal pngcairo size 1100,500 noenhanced
set output '${scene_dir}steps_per_second.png'
set title '${scene}: steps per second over frames (2 CPU threads)'
set xlabel 'frame'
set ylabel 'steps per second'
set yrange [0:*]
plot ${fps_plot}
set output '${scene_dir}particles.png'
set title '${scene}: particle count over frames'
set ylabel 'particles'
plot ${count_plot}
GNUPLOT
  plotted=$((plotted + 1))
  echo "plot_bench: ${scene_dir}steps_per_second.png, ${scene_dir}particles.png"
done
[ "$plotted" -gt 0 ] || { echo "plot_bench: no <scene>/<method>/frames.csv under '$out_dir'" >&2; exit 1; }
