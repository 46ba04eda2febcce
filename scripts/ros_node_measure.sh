#!/usr/bin/env bash
# Measures lvslam_node on a replayed bag (docs/benchmarks.md, "ROS node"):
# the sequence is converted with `lvslam convert to-bag`, played with
# rosbag play --clock at RATE into the node on a private roscore, and the
# node's odometry is recorded. Prints the node's drop and latency lines and
# the odometry's ATE against the ground truth and against `lvslam run`'s
# online trajectory.tum on the same sequence (run with the same DETERMINISTIC).
#   scripts/ros_node_measure.sh SEQUENCE_DIR [RATE=1] [deterministic] [WORK=out/ros-measure]
# Needs a build with LVSLAM_WITH_ROS (build/bin/lvslam_node, build/bin/odometry_recorder).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
SEQ=$(cd "$1" && pwd) RATE=${2:-1} DET=${3:-} WORK=$(realpath -m "${4:-out/ros-measure}")
BIN=$root/build/bin
det_flag="" det_param=false
if [ "$DET" = deterministic ]; then det_flag=--deterministic det_param=true; fi
rm -rf "$WORK"
source "$root/tests/ros/ros_test_env.sh"
cd "$WORK"
"$BIN/lvslam" convert to-bag --sequence "$SEQ" --out seq.bag > /dev/null
"$BIN/lvslam" run --sequence "$SEQ" $det_flag --out run > run.log
start_roscore > /dev/null
"$BIN/odometry_recorder" /lvslam/odometry odometry.tum sigmas.txt > recorder.log 2>&1 &
children+=($!)
recorder=${children[-1]}
rosparam set /use_sim_time true
"$BIN/lvslam_node" __name:=lvslam _preset:="$WORK/seq.preset.yaml" _out:="$WORK/node" _deterministic:=$det_param \
  > node.log 2>&1 &
children+=($!)
node=${children[-1]}
wait_for_line node.log "lvslam_node: mode" 20
rosbag play --clock --delay 2 --quiet --rate "$RATE" seq.bag > play.log 2>&1
stop_process "$node" 300
node_code=$stopped_code
sleep 0.5
stop_process "$recorder" 10
ate() { sed -n 's/.*"ate": {"rmse": \([^,]*\),.*/\1/p'; }
echo "rate ${RATE}x ${DET:-threaded}; node exit $node_code, recorder exit $stopped_code"
grep -o "lvslam_node: [0-9]* sensor items.*\|lvslam_node: publish latency.*" node.log | sed 's/\x1b\[0m//g'
echo "poses: lvslam run $(wc -l < run/trajectory.tum), odometry recorded $(wc -l < odometry.tum)"
echo "ATE rmse node vs ground truth: $("$BIN/lvslam" eval --sequence "$SEQ" --est odometry.tum --json | ate) m"
echo "ATE rmse lvslam run vs ground truth: $("$BIN/lvslam" eval --sequence "$SEQ" --est run/trajectory.tum --json | ate) m"
echo "ATE rmse node vs lvslam run, no alignment: $("$BIN/lvslam" eval --gt run/trajectory.tum --gt-frame camera \
  --est odometry.tum --est-frame camera --align none --json | ate) m"
