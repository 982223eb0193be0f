#!/usr/bin/env bash
# Configures and builds the one instrumented build (./build-asan) that both the sanitizer suite
# (scripts/test-sanitizers.sh) and the fuzzers (scripts/fuzz.sh) run: clang++ at -O1 with
# AddressSanitizer + UndefinedBehaviorSanitizer (-fno-sanitize-recover), the library stages also
# with libFuzzer's coverage (-fsanitize=fuzzer-no-link), the libFuzzer targets of fuzz/ beside
# the tests. One build instead of two keeps CI affordable (docs/reliability.md).
# Usage: scripts/sanitized-build.sh [TARGET...]   (no target: everything)
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GRPVSS_ASAN_BUILD_DIR:-$here/build-asan}"
jobs="${GRPVSS_JOBS:-$(nproc)}"

# clang and its sanitizer/libFuzzer runtimes (Debian 12: clang 14), installed like setup.sh does.
for package in clang libclang-rt-14-dev; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    if [ "$(id -u)" = 0 ]; then
      apt-get update -q >/dev/null
      DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$package" >/dev/null
    else
      echo "sanitized-build: missing Debian package $package (run as root to install it)" >&2
      exit 1
    fi
  fi
done

launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
flags="-O1 -g -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
link="-fsanitize=address,undefined"
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Sanitize \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="$link" -DCMAKE_SHARED_LINKER_FLAGS="$link" \
  -DCMAKE_MODULE_LINKER_FLAGS="$link" \
  -DGRPVSS_BUILD_BENCHMARKS=OFF -DGRPVSS_BUILD_FUZZERS=ON >/dev/null
if [ "$#" -gt 0 ]; then
  cmake --build "$build_dir" -j "$jobs" --target "$@"
else
  cmake --build "$build_dir" -j "$jobs"
fi
