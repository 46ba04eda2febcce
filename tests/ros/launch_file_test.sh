#!/usr/bin/env bash
# The M2DGR launch file resolves through the build tree's ROS package
# (build/ros/lvslam): roslaunch finds lvslam_node and its parameters, and
# with bag:= it adds rosbag play.
#   launch_file_test.sh ROS_PACKAGE_DIR WORK
set -euo pipefail
export ROS_PACKAGE_PATH=$1 ROS_HOME=$2/ros_home ROS_LOG_DIR=$2/ros_log
mkdir -p "$2"
args=$(roslaunch --args /lvslam lvslam m2dgr.launch rviz:=false)
echo "$args"
[[ "$args" == */lvslam/lvslam_node* ]] || { echo "FAIL: roslaunch does not find lvslam_node"; exit 1; }
nodes=$(roslaunch --nodes lvslam m2dgr.launch rviz:=false bag:=/data/street_01.bag)
echo "$nodes"
[ "$(echo "$nodes" | sort | tr '\n' ' ')" = "/lvslam /player " ] || { echo "FAIL: nodes with bag:= are not lvslam and player"; exit 1; }
params=$(roslaunch --dump-params lvslam m2dgr.launch rviz:=false)
for p in "/lvslam/preset: m2dgr" "/lvslam/world_frame: map" "/use_sim_time: false"; do
  grep -qF "$p" <<< "$params" || { echo "FAIL: no parameter '$p' in: $params"; exit 1; }
done
echo PASS
