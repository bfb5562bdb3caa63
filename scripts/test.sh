#!/usr/bin/env bash
# The README's test command: installs what is missing, checks the formatting, builds (Release,
# -Werror), runs every tier (on the best vector form the CPU has), then the unit tier again on each
# lower form: SPH_SIMD=scalar always, SPH_SIMD=avx2 where the CPU has AVX-512 and AVX2 (on a CPU
# whose best is AVX2 the first run already was), then the fuzz targets.
# SPH_SANITIZE=1 also builds build-asan/ with AddressSanitizer + UndefinedBehaviorSanitizer and runs
# every tier but the scenario tier there (the AVX-512 forms included, where the CPU has them).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/check_format.sh
bash scripts/build.sh -DSPH_WERROR=ON
ctest --test-dir build --output-on-failure -j 2
SPH_SIMD=scalar ctest --test-dir build --output-on-failure -j 2 -L unit
if grep -qw avx512f /proc/cpuinfo && grep -qw avx2 /proc/cpuinfo && grep -qw fma /proc/cpuinfo; then
  SPH_SIMD=avx2 ctest --test-dir build --output-on-failure -j 2 -L unit
fi
# The libFuzzer targets (tests/fuzz/README.md): build-fuzz/ with clang, each target for 20 s from a
# copy of its seed corpus; any finding fails the test command.
bash scripts/run_fuzz.sh
if [ "${SPH_SANITIZE:-0}" = "1" ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPH_SANITIZE=ON -DSPH_WERROR=ON
  cmake --build build-asan -j "$(nproc)"
  # A leak inside libzmq itself is suppressed (tests/lsan_suppressions.txt says which and why).
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan_suppressions.txt" \
    ctest --test-dir build-asan --output-on-failure -j 2 -LE scenario
fi
