#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/) into ./build-fuzz (scripts/fuzz-build.sh: clang++,
# ASan + UBSan) and runs each for a bounded time.
# Usage: scripts/fuzz.sh [SECONDS_PER_TARGET] [TARGET...]
# Default 20 s per target (CI); pass e.g. 600 for a longer campaign. The committed seeds in
# fuzz/corpus/<target>/ are read; new inputs go to build-fuzz/corpus/<target>/ (not committed);
# a crash, leak, UB report, timeout or unexpected exception leaves its reproducer in
# build-fuzz/artifacts/<target>/ and makes this script fail. docs/reliability.md.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
seconds="${1:-20}"
shift || true
targets=("$@")
if [ "${#targets[@]}" -eq 0 ]; then
  targets=(robot environment path path_yaml profile_table certificate certificate_checker
           trajectory_csv trajectory_json urscript krl rapid urdf srdf cell mesh)
fi
build_dir="${GRPVSS_FUZZ_BUILD_DIR:-$here/build-fuzz}"

# Only the targets asked for are built, each with the stages it needs.
bash "$here/scripts/fuzz-build.sh" "${targets[@]/%/_fuzzer}"

# Leaks are findings; UBSan reports abort (the targets are built with -fno-sanitize-recover).
export ASAN_OPTIONS="${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}"
export UBSAN_OPTIONS="${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}"
# Leaks inside third-party libraries that are not ours to fix, each listed and explained there.
export LSAN_OPTIONS="${LSAN_OPTIONS:-suppressions=$here/fuzz/lsan.supp}"
status=0
summary=()
for target in "${targets[@]}"; do
  corpus="$build_dir/corpus/$target"
  artifacts="$build_dir/artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  log="$build_dir/$target.log"
  echo "fuzz: $target for ${seconds}s" >&2
  # -timeout: one input taking longer than 10 s is a hang; -rss_limit_mb bounds memory.
  if "$build_dir/fuzz/${target}_fuzzer" "$corpus" "$here/fuzz/corpus/$target" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    runs="$(grep -o 'Done [0-9]* runs' "$log" | grep -o '[0-9]*' || echo '?')"
    summary+=("$target: $runs executions in ${seconds}s, no finding")
  else
    status=1
    summary+=("$target: FINDING (see $log and $artifacts/)")
    tail -n 40 "$log" >&2
  fi
done
printf 'fuzz: %s\n' "${summary[@]}"
exit "$status"
