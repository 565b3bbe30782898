#!/usr/bin/env bash
# Builds the libFuzzer targets with clang (ASan + UBSan) and runs each for a bounded time, both at once.
# Usage: bash scripts/fuzz.sh [SECONDS_PER_FUZZER]   (default 60; CI uses the default)
# Seeds: the tiny files in fuzz/corpus/ plus, copied at run time, the RUBE samples in ../shared and the
# scenes and effects configs in scenes/. The grown corpus lives in a temporary folder and is thrown away;
# a crashing input is kept in build-fuzz/artifacts/ and the script fails.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build=build-fuzz
shared="${CONTACTFX_SHARED_DIR:-../shared}"

CC=clang CXX=clang++ cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCONTACTFX_BUILD_FUZZ=ON \
  -DCONTACTFX_BUILD_APPS=OFF -DCONTACTFX_BUILD_TESTS=OFF -DCONTACTFX_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j"$(nproc)" --target rube_fuzzer effects_fuzzer

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
mkdir -p "$work/rube" "$work/effects" "$build/artifacts"
cp fuzz/corpus/rube/* "$work/rube/"
cp fuzz/corpus/effects/* scenes/*.effects.json "$work/effects/"
for scene in scenes/*.json "$shared"/rube-samples/*.json; do
  case "$scene" in *.effects.json) ;; *) [ -f "$scene" ] && cp "$scene" "$work/rube/" ;; esac
done

export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
pids=()
for name in rube effects; do
  "$build/fuzz/${name}_fuzzer" "$work/$name" -dict="fuzz/$name.dict" -max_total_time="$seconds" \
    -timeout=10 -rss_limit_mb=2048 -max_len=65536 -print_final_stats=1 \
    -artifact_prefix="$build/artifacts/${name}-" >"$work/$name.log" 2>&1 &
  pids+=($!)
done
status=0
for i in 0 1; do
  name=$([ $i -eq 0 ] && echo rube || echo effects)
  if wait "${pids[$i]}"; then
    echo "fuzz $name: ok ($(grep -E 'stat::number_of_executed_units' "$work/$name.log" | awk '{print $2}') runs in ${seconds} s)"
  else
    status=1
    echo "fuzz $name: FAILED"
    tail -60 "$work/$name.log"
  fi
done
exit $status
