#!/usr/bin/env bash
# The README's test command: installs what is missing, builds (Release, -Werror), runs every test.
# SPH_SANITIZE=1 also builds build-asan/ with AddressSanitizer + UndefinedBehaviorSanitizer and runs
# the unit and scene tests there (the 900-frame scenario tier is left to the Release build).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install_deps.sh
bash scripts/build.sh -DSPH_WERROR=ON
ctest --test-dir build --output-on-failure -j 2
if [ "${SPH_SANITIZE:-0}" = "1" ]; then
  cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DSPH_SANITIZE=ON -DSPH_WERROR=ON
  cmake --build build-asan -j "$(nproc)"
  # A leak inside libzmq itself is suppressed (tests/lsan_suppressions.txt says which and why).
  LSAN_OPTIONS="suppressions=$PWD/tests/lsan_suppressions.txt" \
    ctest --test-dir build-asan --output-on-failure -j 2 -E ScenarioHealth
fi
