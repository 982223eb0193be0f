#!/usr/bin/env bash
# Builds everything and runs the whole test suite; exits non-zero when any test fails.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh"
build_dir="${GRPVSS_BUILD_DIR:-$here/build}"
cd "$build_dir"
ctest --output-on-failure -j "${GRPVSS_JOBS:-$(nproc)}"
