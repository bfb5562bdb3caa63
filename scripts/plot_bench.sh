#!/usr/bin/env bash
# Plots sph_bench output (the thesis's figures 5.1-5.11): steps_per_second.png and particles.png,
# one line per method, each method in the same colour in both plots and for both of its lines
# (total solid, L0 dashed), and perceptual_budget.png: the share of visible particles over the
# foveated method's perceptual budget, per frame. Takes a matrix (OUT_DIR/<scene>/<method>/frames.csv) or a single run
# (OUT_DIR/frames.csv with summary.json beside it; the plots go into OUT_DIR). Uses gnuplot (Debian
# gnuplot-nox, installed by scripts/install_deps.sh).
#   usage: scripts/plot_bench.sh [OUT_DIR]   (default bench_out)
set -euo pipefail
out_dir="${1:-bench_out}"
command -v gnuplot >/dev/null || { echo "plot_bench: gnuplot missing (run scripts/install_deps.sh)" >&2; exit 1; }
[ -d "$out_dir" ] || { echo "plot_bench: no folder '$out_dir'" >&2; exit 1; }

colour_of() {  # one colour per method, the same in every figure
  case "$1" in
    regular) echo "#1b9e77" ;; surface) echo "#d95f02" ;; gaze) echo "#7570b3" ;; hybrid) echo "#e7298a" ;;
    foveated) echo "#66a61e" ;;
    *) echo "#666666" ;;
  esac
}
json_field() {  # json_field FILE KEY: a top-level string or number field of summary.json
  sed -n "s/^  \"$2\": \"\{0,1\}\([^\",]*\)\"\{0,1\},\{0,1\}$/\1/p" "$1" | head -n 1
}

# plot DIR TITLE METHOD:CSV...: both figures into DIR.
plot() {
  local dir=$1 title=$2 fps_plot="" count_plot="" budget_plot="" entry m csv c
  shift 2
  for entry in "$@"; do
    m=${entry%%:*} csv=${entry#*:} c=$(colour_of "$m")
    # Columns: 1 frame, 3 particles, 4 levels (the counts per level, L0 first), 10 steps_per_s,
    # 24 visible, 25 over_budget (see bench_output.cpp).
    fps_plot+="${fps_plot:+, }'$csv' using 1:10 with lines lw 1.5 lc rgb '$c' title '$m'"
    count_plot+="${count_plot:+, }'$csv' using 1:3 with lines lw 2 lc rgb '$c' title '$m total'"
    [ "$m" = foveated ] && budget_plot+="${budget_plot:+, }'$csv' using 1:(\$24>0?100.0*\$25/\$24:0) with lines lw 1.5 lc rgb '$c' title '$m'"
    count_plot+=", '$csv' using 1:(real(word(strcol(4), 1))) with lines lw 1 dt 2 lc rgb '$c' title '$m L0'"
  done
  gnuplot <<GNUPLOT
set datafile separator ','
set key outside right top
set grid
set terminal pngcairo size 1100,500 noenhanced
set output '${dir}/steps_per_second.png'
set title '${title}: steps per second over frames'
set xlabel 'frame'
set ylabel 'steps per second'
set yrange [0:*]
plot ${fps_plot}
set output '${dir}/particles.png'
set title '${title}: particle count over frames'
set ylabel 'particles'
plot ${count_plot}
GNUPLOT
  echo "plot_bench: ${dir}/steps_per_second.png, ${dir}/particles.png"
  [ -n "$budget_plot" ] || return 0
  gnuplot <<GNUPLOT
set datafile separator ','
set key outside right top
set grid
set terminal pngcairo size 1100,500 noenhanced
set output '${dir}/perceptual_budget.png'
set title '${title}: visible particles over the perceptual budget'
set xlabel 'frame'
set ylabel 'per cent of visible particles'
set yrange [0:*]
plot ${budget_plot}
GNUPLOT
  echo "plot_bench: ${dir}/perceptual_budget.png"
}

plotted=0
if [ -f "$out_dir/frames.csv" ]; then  # a single run: sph_bench --scene S [--method M]
  summary="$out_dir/summary.json"
  method=$( [ -f "$summary" ] && json_field "$summary" method || true)
  scene=$( [ -f "$summary" ] && json_field "$summary" scene || true)
  plot "${out_dir%/}" "${scene:-run}" "${method:-run}:$out_dir/frames.csv"
  plotted=1
fi
for scene_dir in "$out_dir"/*/; do
  [ -d "$scene_dir" ] || continue
  scene="$(basename "$scene_dir")"
  entries=()
  for m in regular surface gaze hybrid foveated; do
    [ -f "$scene_dir/$m/frames.csv" ] && entries+=("$m:$scene_dir$m/frames.csv")
  done
  [ ${#entries[@]} -gt 0 ] || continue
  plot "${scene_dir%/}" "$scene" "${entries[@]}"
  plotted=$((plotted + 1))
done
[ "$plotted" -gt 0 ] || { echo "plot_bench: no frames.csv nor <scene>/<method>/frames.csv under '$out_dir'" >&2; exit 1; }
