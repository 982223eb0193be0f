#!/usr/bin/env bash
# Builds the whole library, CLI and test suite with AddressSanitizer + UndefinedBehavior-
# Sanitizer (g++, -O1, ./build-asan) and runs the whole ctest suite under them. Any ASan
# report, leak or UBSan report fails the run. The Python module is left out: an ASan-built
# extension cannot be loaded into an uninstrumented python3. Suppressions (none at present) and the `heavy` label: see
# docs/reliability.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GRPVSS_ASAN_BUILD_DIR:-$here/build-asan}"
jobs="${GRPVSS_JOBS:-$(nproc)}"
# -g1: line tables only, which is all a sanitizer report prints; full -g compiles ~25% slower.
flags="-O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
# -no-pie (executables only): UBSan's check-site data makes a position-independent test binary
# carry ~3.7 million relocations, which the loader applied at every start (0.17 s of the 0.62 s
# each of the ~1,000 test processes and every CLI run paid); docs/reliability.md#ci-time.
launcher=()
# ccache, when the machine has it, shares compiled objects between checkouts (not required).
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Sanitize "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined -no-pie" \
  -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DCMAKE_MODULE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DGRPVSS_BUILD_BENCHMARKS=OFF -DGRPVSS_BUILD_PYTHON=OFF >/dev/null
cmake --build "$build_dir" -j "$jobs"
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:abort_on_error=1:strict_string_checks=1:detect_stack_use_after_return=1}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
cd "$build_dir"
# The 100,000-step memory test (label heavy) is about Release memory use; it runs in scripts/test.sh.
# The tests that are no gtest case, and the absurd-input cases (their 30 s timeout each is the
# hang check), through ctest; every other gtest case in one process per suite: each sanitized
# process costs ~0.45 s to start and exit (docs/reliability.md#ci-time).
status=0
ctest --output-on-failure -j "$jobs" -LE heavy -R '^([^.]*|AbsurdInput[.].*)$' || status=$?
python3 "$here/scripts/run-gtest-suites.py" . --jobs "$jobs" -LE heavy -E '^AbsurdInput[.]' || status=$?
exit "$status"
