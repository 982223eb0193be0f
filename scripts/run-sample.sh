#!/usr/bin/env bash
# The main job on the embedded IBM 7545 sample (data/ibm7545).
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
bash "$here/scripts/setup.sh" >&2
build_dir="${GRPVSS_BUILD_DIR:-$here/build}"
"$build_dir/grpvss" verify \
  --robot "$here/data/ibm7545/robot.txt" \
  --env "$here/data/ibm7545/environment.txt" \
  --path "$here/data/ibm7545/path.txt" --tolerance 0.5 "$@"
