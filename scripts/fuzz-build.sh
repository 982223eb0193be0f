#!/usr/bin/env bash
# Configures ./build-fuzz (clang++ 14, ASan + UBSan at -O1, the library stages with libFuzzer's
# coverage -fsanitize=fuzzer-no-link, -DGRPVSS_BUILD_FUZZERS=ON, no tests) and builds the given
# fuzz targets only: each links just the stages its reader needs, so only the certificate
# checker's target compiles the CGAL stage (docs/reliability.md#fuzzing).
# Usage: scripts/fuzz-build.sh TARGET_fuzzer...
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build_dir="${GRPVSS_FUZZ_BUILD_DIR:-$here/build-fuzz}"
jobs="${GRPVSS_JOBS:-$(nproc)}"

# clang and its sanitizer/libFuzzer runtimes (Debian 12: clang 14), installed like setup.sh does.
for package in clang libclang-rt-14-dev; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    if [ "$(id -u)" = 0 ]; then
      apt-get update -q >/dev/null
      DEBIAN_FRONTEND=noninteractive apt-get install -y -q "$package" >/dev/null
    else
      echo "fuzz-build: missing Debian package $package (run as root to install it)" >&2
      exit 1
    fi
  fi
done

launcher=()
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# -g1: line tables only, which is all a sanitizer report prints; full -g compiles ~25% slower.
flags="-O1 -g1 -fsanitize=address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer"
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Fuzz \
  -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_C_COMPILER=clang "${launcher[@]}" \
  -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_C_FLAGS="$flags" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=address,undefined" \
  -DGRPVSS_BUILD_TESTS=OFF -DGRPVSS_BUILD_BENCHMARKS=OFF -DGRPVSS_BUILD_FUZZERS=ON >/dev/null
cmake --build "$build_dir" -j "$jobs" --target "$@"
