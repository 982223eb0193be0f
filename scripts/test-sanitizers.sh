#!/usr/bin/env bash
# Builds the whole library, CLI, test suite and fuzz targets with clang AddressSanitizer +
# UndefinedBehaviorSanitizer (-O1, ./build-asan, scripts/sanitized-build.sh) and runs the whole
# ctest suite under them. Any ASan report, leak or UBSan report fails the run. Suppressions
# (none at present) and the `heavy` label: see docs/reliability.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GRPVSS_ASAN_BUILD_DIR:-$here/build-asan}"
jobs="${GRPVSS_JOBS:-$(nproc)}"
bash "$here/scripts/sanitized-build.sh"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build_dir"
# The label heavy (100,000-step memory test, oracle shards 1-7) runs in scripts/test.sh only.
ctest --output-on-failure -j "$jobs" -LE heavy
