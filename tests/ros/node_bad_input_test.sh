#!/usr/bin/env bash
# lvslam_node under bad input on its topics: empty clouds, clouds
# without per-point time or without z, images in an unreadable encoding or
# of a size that is not the calibration's, a scan stamped before the last.
# Each kind three times: each must be logged exactly once, counted in the
# shutdown summary, and the node must live on and stop cleanly.
#   node_bad_input_test.sh LVSLAM LVSLAM_NODE BAD_INPUT_PUBLISHER WORK
LVSLAM=$1 NODE=$2 PUBLISHER=$3 WORK=$4
rm -rf "$WORK"
source "$(dirname "$0")/ros_test_env.sh"
cd "$WORK"

"$LVSLAM" simulate --scenario room --duration 1 --out seq > /dev/null
"$LVSLAM" convert to-bag --sequence seq --out seq.bag > /dev/null
width=$(sed -n 's/^ *width: *\([0-9]*\).*/\1/p' seq.preset.yaml)
height=$(sed -n 's/^ *height: *\([0-9]*\).*/\1/p' seq.preset.yaml)
start_roscore
"$NODE" __name:=lvslam _preset:="$WORK/seq.preset.yaml" _out:="$WORK/node" > node.log 2>&1 &
node=$!
children+=($node)
wait_for_line node.log "lvslam_node: mode fused" 20
"$PUBLISHER" /velodyne_points /camera/image_raw "$width" "$height" || fail "the publisher failed"
kill -0 "$node" 2>/dev/null || fail "lvslam_node died: $(cat node.log)"
stop_process "$node" 60
node_code=$stopped_code
cat node.log
[ "$node_code" -lt 128 ] || fail "lvslam_node was killed by signal $((node_code - 128))"
[ "$node_code" -le 1 ] || fail "lvslam_node exited with $node_code"
for kind in "empty cloud" "cloud without per-point time" "undecodable cloud" "unsupported image encoding" \
            "image size not the calibration's" "out of order"; do
  logged=$(grep -c -- "$kind: " node.log || true)
  [ "$logged" = 1 ] || fail "'$kind' logged $logged times, not once"
  grep -q -- "3 $kind" node.log || fail "the summary does not count 3 '$kind': $(grep dropped: node.log)"
done
echo "PASS"
