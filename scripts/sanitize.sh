#!/usr/bin/env bash
# The fast test tier (ctest label `unit`) under AddressSanitizer and UndefinedBehaviorSanitizer:
# a g++ build in build-asan/ (or $CAIRN_ASAN_DIR), -O1, no -march=native, then `ctest -L unit`.
# Any sanitizer report fails the test that triggered it. See docs/development.md.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${CAIRN_ASAN_DIR:-build-asan}"
cmake -S . -B "$build" -DCAIRN_SANITIZE=ON -DCAIRN_NATIVE=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  "-DCMAKE_CXX_FLAGS_RELWITHDEBINFO=-O1 -g" >/dev/null
# only what the fast tier runs
cmake --build "$build" -j"$(nproc)" --target test_core test_dem_unit test_fuzz test_compare test_app cairn >/dev/null
# leaks inside engine libraries only, each one named and explained in the file
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=0:detect_stack_use_after_return=0"
export LSAN_OPTIONS="suppressions=$PWD/scripts/lsan.supp:print_suppressions=0"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"
ctest --test-dir "$build" -L unit --output-on-failure -j"$(nproc)"
