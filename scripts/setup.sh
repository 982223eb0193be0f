#!/usr/bin/env bash
# Installs the Debian packages GRPVSS needs (when run as root and something is missing),
# then configures and builds into ./build. Safe to run again: it only does what is missing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

debian_packages=(
  build-essential cmake pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev libboost-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev libssl-dev
  libgtest-dev libgmock-dev libbenchmark-dev
)
missing=()
for package in "${debian_packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed" || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing ${missing[*]}" >&2
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}" >/dev/null
  else
    echo "setup: missing Debian packages: ${missing[*]} (run as root to install them)" >&2
    exit 1
  fi
fi

# The HTML report viewer (src/viewer, three.js) is bundled at build time from npm packages;
# the browser test drives Debian's chromium. Both are optional: without them the build warns
# and `grpvss animate` / `verify --html` are unavailable.
if [ ! -d "$here/src/viewer/node_modules" ]; then
  if command -v npm >/dev/null 2>&1; then
    echo "setup: npm ci in src/viewer" >&2
    (cd "$here/src/viewer" && npm ci --no-audit --no-fund >/dev/null)
  else
    echo "setup: node/npm missing: the HTML viewer will not be built" >&2
  fi
fi
if ! command -v chromium >/dev/null 2>&1 || ! command -v rsvg-convert >/dev/null 2>&1; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing chromium librsvg2-bin (viewer tests, SVG previews)" >&2
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q chromium librsvg2-bin >/dev/null
  else
    echo "setup: chromium missing: the viewer browser test will not be registered" >&2
  fi
fi

build_dir="${GRPVSS_BUILD_DIR:-$here/build}"
jobs="${GRPVSS_JOBS:-$(nproc)}"
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$build_dir" -j "$jobs"
