#!/usr/bin/env bash
# Builds the libFuzzer harnesses of fuzz/ with clang (-DLVSLAM_FUZZ=ON,
# ASan + UBSan) in build-fuzz/ and runs each for SECONDS (default 60) on its
# seed corpus, one after the other; prints executions and findings per
# harness. Exit 1 when any harness found something (crash, sanitizer report,
# uncaught exception other than lvslam::Error, timeout, memory over 2 GB).
#   scripts/fuzz.sh [SECONDS] [HARNESS...]     e.g. scripts/fuzz.sh 300 tum times_file
#   LVSLAM_FUZZ_RUNS=10000000 scripts/fuzz.sh 7200 tum   stop at 10 M executions
# Inputs the fuzzer found new are kept in build-fuzz/fuzz-work/NAME/corpus,
# findings in build-fuzz/fuzz-work/NAME/findings (crash-*, timeout-*, oom-*):
# a finding, once fixed, goes to fuzz/regressions/NAME/ (ctest replays it).
set -euo pipefail
cd "$(dirname "$0")/.."

seconds=${1:-60}
[ $# -gt 0 ] && shift
harnesses=(sequence_yaml sensor_preset config_yaml times_file scan_file tum kitti_poses png_image json ply saved_map
           pointcloud2 bag_records ros_image)
[ $# -gt 0 ] && harnesses=("$@")
build=${LVSLAM_FUZZ_BUILD:-build-fuzz}
runs=${LVSLAM_FUZZ_RUNS:--1}

CC=clang CXX=clang++ cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DLVSLAM_FUZZ=ON \
  -DLVSLAM_BUILD_TESTS=OFF -DLVSLAM_BUILD_BENCH=OFF >/dev/null
nice -n 10 cmake --build "$build" -j2 --target "${harnesses[@]/#/fuzz_}"

printf '%-14s %12s %9s %9s %s\n' harness executions exec/s findings log
found=0
for h in "${harnesses[@]}"; do
  work="$build/fuzz-work/$h"
  mkdir -p "$work/corpus" "$work/findings"
  touch "$work/started"  # findings of earlier runs stay, but are not counted again
  # New inputs go to the first folder (the build's); the repository's seeds are read only.
  set +e
  nice -n 15 "$build/bin/fuzz_$h" -max_total_time="$seconds" -runs="$runs" -timeout=10 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$work/findings/" "$work/corpus" "fuzz/corpus/$h" >"$work/log" 2>&1
  rc=$?
  set -e
  execs=$(awk '/stat::number_of_executed_units/ {print $2}' "$work/log")
  rate=$(awk '/stat::average_exec_per_sec/ {print $2}' "$work/log")
  findings=$(find "$work/findings" -type f -newer "$work/started" | wc -l)
  if [ "$rc" -ne 0 ] && [ "$findings" -eq 0 ]; then findings="rc=$rc"; fi
  [ "$findings" != 0 ] && found=1
  printf '%-14s %12s %9s %9s %s\n' "$h" "${execs:-?}" "${rate:-?}" "$findings" "$work/log"
done
exit "$found"
