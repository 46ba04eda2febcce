# Sourced by the lvslam_node tests: a private roscore on a free port and a
# scratch folder whose bags are removed when the test ends, whatever way it ends.
# Before sourcing: WORK (scratch folder). Gives: start_roscore, wait_for_line,
# stop_process (stopped_code), fail.
set -euo pipefail
mkdir -p "$WORK"
export ROS_HOME="$WORK/ros_home" ROS_LOG_DIR="$WORK/ros_log" ROS_HOSTNAME=localhost
unset ROS_IP
children=()
cleanup() {
  # Only what this test started, by its own process ids.
  for pid in "${children[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  sleep 1
  for pid in "${children[@]}"; do kill -KILL "$pid" 2>/dev/null || true; done
  rm -f "$WORK"/*.bag  # the largest files by far; everything else stays to look at
}
trap cleanup EXIT

fail() { echo "FAIL: $*" >&2; exit 1; }

port_free() { ! (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null; }

# roscore on a port nobody else uses (several test runs share the machine).
start_roscore() {
  local port
  for attempt in 1 2 3 4 5; do
    port=$((20000 + RANDOM % 40000))
    port_free "$port" || continue
    export ROS_MASTER_URI="http://localhost:$port"
    roscore -p "$port" > "$WORK/roscore.log" 2>&1 &
    children+=($!)
    for _ in $(seq 1 100); do
      if ! port_free "$port"; then echo "roscore on port $port"; return 0; fi
      kill -0 "${children[-1]}" 2>/dev/null || break
      sleep 0.1
    done
  done
  cat "$WORK/roscore.log" >&2
  fail "roscore did not start"
}

# wait_for_line FILE PATTERN SECONDS
wait_for_line() {
  for _ in $(seq 1 $(($3 * 10))); do
    grep -q -- "$2" "$1" 2>/dev/null && return 0
    sleep 0.1
  done
  fail "no line '$2' in $1 within $3 s: $(tail -5 "$1" 2>/dev/null)"
}

# stop_process PID SECONDS: SIGINT, then wait; sets stopped_code to the exit
# code (>128: killed by a signal; SIGKILL after SECONDS without exiting).
stop_process() {
  kill -INT "$1" 2>/dev/null || true
  for _ in $(seq 1 $(($2 * 10))); do
    kill -0 "$1" 2>/dev/null || break
    sleep 0.1
  done
  if kill -0 "$1" 2>/dev/null; then kill -KILL "$1"; fi
  stopped_code=0
  wait "$1" || stopped_code=$?
}
