#!/usr/bin/env bash
# Builds the CLI and the batch tests with ThreadSanitizer (g++, -O1, ./build-tsan) and runs
# the batch suites, whose runs use two worker threads (the library's runner with 2 threads,
# the CLI with -j 2), and the cell's lazily built obstacles shared between threads. Only
# what they need is built: the library, the CLI and the test files
# tests/app/batch_*_test.cpp (GRPVSS_TEST_FILTER). Any ThreadSanitizer report fails the run:
# reports go to build-tsan/tsan-reports/ (the CLI runs as a child of the tests) and are
# printed at the end. docs/batch.md#threads.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GRPVSS_TSAN_BUILD_DIR:-$here/build-tsan}"
jobs="${GRPVSS_JOBS:-$(nproc)}"
flags="-O1 -fsanitize=thread"
launcher=()
# ccache, when the machine has it, shares compiled objects between checkouts (not required).
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Tsan "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=thread" \
  -DGRPVSS_BUILD_BENCHMARKS=OFF -DGRPVSS_BUILD_FUZZERS=OFF \
  -DGRPVSS_TEST_FILTER='/app/batch_|/certify/obstacle_set|/support/text_files|/support/cli_run' >/dev/null
cmake --build "$build_dir" -j "$jobs" --target grpvss_tests grpvss
reports="$build_dir/tsan-reports"
rm -rf "$reports" && mkdir -p "$reports"
export TSAN_OPTIONS="${TSAN_OPTIONS:-halt_on_error=1:second_deadlock_stack=1:log_path=$reports/tsan}"
status=0
# BatchMemory (label heavy) measures Release memory; under TSan its bound means nothing.
"$build_dir/tests/grpvss_tests" --gtest_filter='Batch*:ObstacleSet.*-BatchMemory.*' || status=$?
if compgen -G "$reports/tsan*" >/dev/null; then
  cat "$reports"/tsan* >&2
  echo "test-tsan: ThreadSanitizer reported the above" >&2
  exit 1
fi
exit "$status"
