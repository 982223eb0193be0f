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
# One target per core at a time (GRPVSS_JOBS, default nproc): each libFuzzer run is single-
# threaded, so two cores fuzz two readers for the same seconds each in half the wall time.
jobs="${GRPVSS_JOBS:-$(nproc)}"
fuzz_one() {
  local target="$1"
  local corpus="$build_dir/corpus/$target" artifacts="$build_dir/artifacts/$target"
  local log="$build_dir/$target.log" result="$build_dir/$target.result"
  mkdir -p "$corpus" "$artifacts"
  # -timeout: one input taking longer than 10 s is a hang; -rss_limit_mb bounds memory.
  if "$build_dir/fuzz/${target}_fuzzer" "$corpus" "$here/fuzz/corpus/$target" \
      -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len=65536 \
      -print_final_stats=1 -artifact_prefix="$artifacts/" >"$log" 2>&1; then
    local runs
    runs="$(grep -o 'Done [0-9]* runs' "$log" | grep -o '[0-9]*' || echo '?')"
    echo "$target: $runs executions in ${seconds}s, no finding" >"$result"
  else
    echo "$target: FINDING (see $log and $artifacts/)" >"$result"
  fi
}
for target in "${targets[@]}"; do
  rm -f "$build_dir/$target.result"
  while [ "$(jobs -rp | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  echo "fuzz: $target for ${seconds}s" >&2
  fuzz_one "$target" &
done
wait
status=0
for target in "${targets[@]}"; do
  result="$build_dir/$target.result"
  if [ ! -f "$result" ]; then
    echo "fuzz: $target: FINDING (the run left no result; see $build_dir/$target.log)"
    status=1
  elif grep -q ': FINDING' "$result"; then
    echo "fuzz: $(cat "$result")"
    tail -n 40 "$build_dir/$target.log" >&2
    status=1
  else
    echo "fuzz: $(cat "$result")"
  fi
done
exit "$status"
