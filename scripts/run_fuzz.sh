#!/usr/bin/env bash
# Builds the libFuzzer targets into build-fuzz/ (clang, ASan + UBSan, tests/fuzz/README.md) and runs
# each for SPH_FUZZ_SECONDS (default 20) from a fresh copy of its seed corpus, so the repository's
# corpus is never modified. Exits 1 when any target finds a crash, a leak, undefined behaviour, a
# timeout or a broken property; the input is kept as build-fuzz/artifacts/<target>-crash-<hash>.
# Extra arguments go to every target (e.g. -jobs=2).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${SPH_FUZZ_SECONDS:-20}"
start=$(date +%s)
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPH_FUZZ=ON -DSPH_WERROR=ON \
  -DCMAKE_CXX_COMPILER=clang++ >/dev/null
cmake --build build-fuzz -j 2
built=$(date +%s)

artifacts="$PWD/build-fuzz/artifacts"
mkdir -p "$artifacts"
# In memory where there is /dev/shm: the gaze-recording target writes a file per input.
scratch=$(mktemp -d -p /dev/shm 2>/dev/null || mktemp -d)
trap 'rm -rf "$scratch"' EXIT
failed=()
summary=()
while read -r target; do
  [ -n "$target" ] || continue
  corpus="$scratch/$target"
  mkdir -p "$corpus"
  cp tests/fuzz/corpus/"$target"/* "$corpus"/
  log="$artifacts/$target.log"
  # -timeout: one input running 10 s is a hang; -rss_limit_mb: a decoder that balloons is a finding.
  # TMPDIR: the gaze-recording target writes its input to a file, here and not in the user's /tmp.
  if TMPDIR="$scratch" "build-fuzz/bin/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/$target-" "$@" "$corpus" >"$log" 2>&1; then
    status=ok
  else
    status=FAILED
    failed+=("$target")
  fi
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)
  corpus_size=$(find "$corpus" -type f | wc -l)
  summary+=("$(printf '%-22s %-6s %12s executions %6s corpus files' "$target" "$status" "${runs:-?}" "$corpus_size")")
done <build-fuzz/fuzz_targets.txt

echo "run_fuzz: build $((built - start)) s, runs $(($(date +%s) - built)) s (${seconds} s per target)"
printf '  %s\n' "${summary[@]}"
if [ ${#failed[@]} -gt 0 ]; then
  for target in "${failed[@]}"; do
    echo "run_fuzz: $target failed; the end of $artifacts/$target.log:" >&2
    tail -n 40 "$artifacts/$target.log" >&2
  done
  exit 1
fi
