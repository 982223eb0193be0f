#!/usr/bin/env bash
# `cmake --install` of the build into a fresh prefix, then a user's project (consumer/) found
# with find_package(grpvss) and built against that prefix alone; its run and the installed CLI
# must give the verdict of the sample (COLLISION). Usage: check_install.sh BUILD_DIR SOURCE_DIR
# CXX_FLAGS LINKER_FLAGS (the flags of the build, so that a sanitizer build links its own)
# [PYTHON PYTHON_DIR] (when the Python module is built: `import grpvss` from PREFIX/PYTHON_DIR
# alone must verify the sample too).
set -euo pipefail
build_dir="$1"
source_dir="$2"
cxx_flags="$3"
linker_flags="$4"
python="${5:-}"
python_dir="${6:-}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cmake --install "$build_dir" --prefix "$work/prefix" >/dev/null
for installed in bin/grpvss include/grpvss/certify/verifier.hpp \
                 lib/cmake/grpvss/grpvssConfig.cmake lib/libgrpvss_certify.a; do
  [ -e "$work/prefix/$installed" ] || { echo "missing after install: $installed" >&2; exit 1; }
done
# The source tree is not on any path the consumer sees: only the prefix.
cmake -S "$source_dir/tests/install/consumer" -B "$work/consumer" \
  -DCMAKE_PREFIX_PATH="$work/prefix" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS="$cxx_flags" -DCMAKE_EXE_LINKER_FLAGS="$linker_flags" >/dev/null
cmake --build "$work/consumer" -j 2 >/dev/null
data="$source_dir/data/ibm7545"
got="$("$work/consumer/verify_sample" "$data/robot.txt" "$data/environment.txt" "$data/path.txt" 0.5)"
echo "consumer: $got"
[ "$got" = "verdict COLLISION, 23 steps" ] || { echo "unexpected consumer result" >&2; exit 1; }
status=0
"$work/prefix/bin/grpvss" verify --robot "$data/robot.txt" --env "$data/environment.txt" \
  --path "$data/path.txt" --tolerance 0.5 --quiet || status=$?
[ "$status" = 1 ] || { echo "installed CLI exited $status, expected 1 (COLLISION)" >&2; exit 1; }
echo "installed CLI: COLLISION (exit 1)"
if [ -n "$python_dir" ]; then
  site="$work/prefix/$python_dir"
  got="$(cd "$work" && PYTHONPATH="$site" "$python" -s -c '
import sys, _grpvss, grpvss
site = sys.argv[1]
assert grpvss.__file__.startswith(site) and _grpvss.__file__.startswith(site), (grpvss.__file__, _grpvss.__file__)
result = grpvss.verify(sys.argv[2] + "/robot.txt", sys.argv[2] + "/environment.txt", sys.argv[2] + "/path.txt", 0.5)
print(f"verdict {result.verdict.name}, {result.step_count} steps")
' "$site" "$data")"
  echo "installed Python module: $got"
  [ "$got" = "verdict COLLISION, 23 steps" ] || { echo "unexpected Python result" >&2; exit 1; }
fi
