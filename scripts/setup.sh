#!/usr/bin/env bash
# Installs the Debian packages GRPVSS needs (when run as root and something is missing),
# then configures and builds into ./build. Safe to run again: it only does what is missing.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

debian_packages=(
  build-essential cmake pkg-config
  libcgal-dev libgmp-dev libmpfr-dev libeigen3-dev libboost-dev
  libcli11-dev nlohmann-json3-dev libfmt-dev nettle-dev
  libgtest-dev libgmock-dev libbenchmark-dev bsdutils
  liburdfdom-dev libassimp-dev libtinyxml2-dev libyaml-cpp-dev
  pybind11-dev python3-dev python3-numpy python3-pytest python3-distributed
  libfcl-dev  # benchmark-only: the FCL peers of tests/bench (docs/performance.md)
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
# its browser test drives Debian's chromium; SVG previews use rsvg-convert. All are required.
need_apt=()
command -v npm >/dev/null 2>&1 || need_apt+=(nodejs npm)
command -v chromium >/dev/null 2>&1 || need_apt+=(chromium)
command -v rsvg-convert >/dev/null 2>&1 || need_apt+=(librsvg2-bin)
if [ "${#need_apt[@]}" -gt 0 ]; then
  if [ "$(id -u)" = 0 ]; then
    echo "setup: installing ${need_apt[*]}" >&2
    apt-get update -q >/dev/null
    DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${need_apt[@]}" >/dev/null
  else
    echo "setup: missing ${need_apt[*]} (run as root to install them)" >&2
    exit 1
  fi
fi
if [ ! -f "$here/src/viewer/node_modules/three/package.json" ] ||
   [ ! -f "$here/src/viewer/node_modules/esbuild/package.json" ] ||
   [ ! -f "$here/src/viewer/node_modules/playwright-core/package.json" ]; then
  echo "setup: npm ci in src/viewer" >&2
  (cd "$here/src/viewer" && npm ci --no-audit --no-fund >/dev/null)
fi

build_dir="${GRPVSS_BUILD_DIR:-$here/build}"
jobs="${GRPVSS_JOBS:-$(nproc)}"
launcher=()
# ccache, when the machine has it, shares compiled objects between checkouts (not required).
command -v ccache >/dev/null 2>&1 && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
cmake -S "$here" -B "$build_dir" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" >/dev/null
cmake --build "$build_dir" -j "$jobs"
