#!/usr/bin/env bash
# Behaviour-unchanged check for refactors (docs/architecture.md#behaviour-unchanged):
#
#   scripts/compare-outputs.sh capture GRPVSS_BINARY DIR   # every output of a fixed command set
#   scripts/compare-outputs.sh compare DIR_BEFORE DIR_AFTER # byte-for-byte, names what differs
#
# The command set covers the thesis output file, the JSON report, the certificate, the HTML
# animation, check-certificate (text and JSON), trajectory and expansion-audit, on the IBM 7545
# sample, the benchmark environments and the PUMA 560, in both modes and both timings. The one
# field that may differ between runs (the report's "generated_at" timestamp) is blanked.
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"

capture() {
  local cli out
  cli="$(realpath "$1")"
  [ -x "$cli" ] || { echo "compare-outputs: not an executable: $1" >&2; exit 2; }
  out="$(realpath -m "$2")"
  [ -e "$out" ] && { echo "compare-outputs: $out exists" >&2; exit 2; }
  # Inputs are named by the same relative paths from every checkout (reports print them).
  local work
  work="$(mktemp -d)"
  ln -s "$here/data" "$work/data"
  mkdir "$work/out"
  local ibm="../data/ibm7545"
  local n=0
  # run NAME ARGS...: stdout, stderr and the exit code of one command, then its output files.
  run() {
    local name="$1"; shift
    local code=0
    (cd "$work/out" && "$cli" "$@" >"$name.stdout" 2>"$name.stderr") || code=$?
    echo "$code" >"$work/out/$name.exit"
    n=$((n + 1))
  }
  local robot="--robot $ibm/robot.txt"
  local sample="$robot --env $ibm/environment.txt --path $ibm/path.txt"
  # shellcheck disable=SC2086
  {
    run verify-sample verify $sample --tolerance 0.5 --out sample.out --json sample.json \
      --certificate sample.cert --html sample.html
    run check-sample check-certificate $sample sample.cert
    run check-sample-json check-certificate $sample sample.cert --json
    run verify-sample-thesis verify $sample --tolerance 0.5 --mode thesis --out thesis.out \
      --json thesis.json
    run verify-sample-sync verify $sample --tolerance 0.5 --timing synchronized \
      --out sync.out --json sync.json --certificate sync.cert
    run check-sample-sync check-certificate $sample --timing synchronized sync.cert
    run verify-sample-cube verify $sample --tolerance 0.5 --offset cube --json cube.json
    run verify-output-sample verify $robot --env $ibm/environment.txt \
      --path $ibm/path-output-sample.txt --tolerance 0.5 --out a3.out --json a3.json \
      --certificate a3.cert
    run verify-table verify $sample --tolerance 0.5 --profile-table \
      ../data/motion/example-table.txt --json table.json --certificate table.cert
    run check-table check-certificate $sample --profile-table \
      ../data/motion/example-table.txt table.cert
    for env in bench-environment bench-environment-cp-line bench-environment-near-miss \
               bench-environment-within-tolerance; do
      run "verify-$env" verify $robot --env "$ibm/$env.txt" --path $ibm/path.txt \
        --tolerance 0.5 --out "$env.out" --json "$env.json" --certificate "$env.cert"
      run "check-$env" check-certificate $robot --env "$ibm/$env.txt" --path $ibm/path.txt \
        "$env.cert"
    done
    run verify-cp-speed verify $sample --tolerance 0.25 --cp-speed 2 --json cp-speed.json \
      --certificate cp-speed.cert
    run trajectory trajectory $robot --path $ibm/path.txt
    run trajectory-json trajectory $robot --path $ibm/path.txt --json
    run trajectory-sync trajectory $robot --path $ibm/path.txt --timing synchronized --step 0.25
    run audit expansion-audit $robot --tolerance 0.5
    run audit-json expansion-audit $robot --tolerance 0.5 --json
    run audit-puma expansion-audit --robot ../data/puma560/robot.txt --tolerance 5 --json
  }
  mv "$work/out" "$out"
  rm -rf "$work"
  # The timestamp is the one field allowed to change (docs/report-schema.md).
  find "$out" -type f \( -name '*.json' -o -name '*.html' \) -print0 |
    xargs -0 sed -i -E 's/"generated_at": ?"[^"]*"/"generated_at":"-"/g'
  echo "compare-outputs: $n commands captured into $out" >&2
}

compare() {
  local before="$1" after="$2"
  if diff -r -q "$before" "$after"; then
    echo "compare-outputs: byte-identical ($(find "$before" -type f | wc -l) files)"
  else
    echo "compare-outputs: DIFFERENT (see above)" >&2
    exit 1
  fi
}

case "${1:-}" in
  capture) capture "$2" "$3" ;;
  compare) compare "$2" "$3" ;;
  *) echo "usage: $0 capture GRPVSS_BINARY DIR | compare DIR_BEFORE DIR_AFTER" >&2; exit 2 ;;
esac
