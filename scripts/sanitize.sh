#!/usr/bin/env bash
# The suite again under AddressSanitizer (leaks included) and UndefinedBehaviorSanitizer, built
# with clang into build-asan/ together with the libFuzzer targets, which then run briefly over the
# committed corpus (tests/fuzz_corpus/: seeds and every input that ever crashed).
# Usage: scripts/sanitize.sh [FUZZ_SECONDS_PER_TARGET]   (default 10; scripts/test.sh calls it)
# MeshLab and Blender load the release library, so their tests run in the release build only.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-10}"
bash "$here/scripts/setup.sh"
cmake -S "$here" -B "$here/build-asan" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ -DMEROMORPH_BUILD_FUZZERS=ON \
  -DMEROMORPH_BUILD_TESTS=ON -DMEROMORPH_BUILD_BENCH=OFF >/dev/null
cmake --build "$here/build-asan" --parallel "$(nproc)"
cd "$here/build-asan"
ASAN_OPTIONS=detect_leaks=1 UBSAN_OPTIONS=print_stacktrace=1 \
  ctest --output-on-failure --parallel "$(nproc)" -E clang_format
bash "$here/scripts/fuzz.sh" "$here/build-asan/fuzz" "$seconds"
