# Optional ROS1 node (LVSLAM_WITH_ROS, ros/): lvslam_node on live topics.
# Debian 12 packages ROS1's roscpp without catkin; its pkg-config files are
# complete, the message packages are headers only. The node publishes TF as
# tf2_msgs/TFMessage itself (what tf2_ros's broadcaster does), so it needs no
# tf2_ros. On by default when everything below is found and the bag
# component (whose decoders it reuses) is on; the core library stays ROS-free.
# Result: the INTERFACE target lvslam_ros_deps, only when the option is ON.
find_package(PkgConfig QUIET)
set(_lvslam_ros_missing "")
if(PkgConfig_FOUND)
  pkg_check_modules(LVSLAM_ROSCPP QUIET IMPORTED_TARGET roscpp)
endif()
if(NOT LVSLAM_ROSCPP_FOUND)
  list(APPEND _lvslam_ros_missing "roscpp (libroscpp-dev)")
endif()
# <variable> <header> <Debian package>
foreach(_entry "NAV_MSGS;nav_msgs/Odometry.h;libnav-msgs-dev"
               "VISUALIZATION_MSGS;visualization_msgs/MarkerArray.h;libvisualization-msgs-dev"
               "DIAGNOSTIC_MSGS;diagnostic_msgs/DiagnosticArray.h;libdiagnostic-msgs-dev"
               "TF2_MSGS;tf2_msgs/TFMessage.h;libtf2-msgs-dev")
  list(GET _entry 0 _name)
  list(GET _entry 1 _header)
  list(GET _entry 2 _package)
  find_path(LVSLAM_${_name}_INCLUDE NAMES ${_header})
  if(NOT LVSLAM_${_name}_INCLUDE)
    list(APPEND _lvslam_ros_missing "${_header} (${_package})")
  endif()
endforeach()
if(NOT LVSLAM_WITH_ROSBAG)
  list(APPEND _lvslam_ros_missing "the ROS1 bag component (LVSLAM_WITH_ROSBAG)")
endif()

if(_lvslam_ros_missing)
  set(_lvslam_ros_found OFF)
else()
  set(_lvslam_ros_found ON)
endif()
option(LVSLAM_WITH_ROS "Build lvslam_node, the ROS1 node (on when Debian's ROS1 packages are found)" ${_lvslam_ros_found})

if(NOT LVSLAM_WITH_ROS)
  if(_lvslam_ros_missing)
    list(JOIN _lvslam_ros_missing ", " _missing_text)
    message(STATUS "lvslam: ROS1 node OFF (missing: ${_missing_text}; scripts/install-deps.sh installs them)")
  else()
    message(STATUS "lvslam: ROS1 node OFF (-DLVSLAM_WITH_ROS=OFF)")
  endif()
  return()
endif()
if(_lvslam_ros_missing)
  list(JOIN _lvslam_ros_missing "\n  " _missing_text)
  message(FATAL_ERROR "LVSLAM_WITH_ROS is ON but these are missing:\n  ${_missing_text}\n"
                      "Install them with scripts/install-deps.sh, or configure with -DLVSLAM_WITH_ROS=OFF.")
endif()

add_library(lvslam_ros_deps INTERFACE)
# The ROS headers are not -Wall -Wextra clean and are not ours.
get_target_property(_lvslam_roscpp_includes PkgConfig::LVSLAM_ROSCPP INTERFACE_INCLUDE_DIRECTORIES)
if(_lvslam_roscpp_includes)
  target_include_directories(lvslam_ros_deps SYSTEM INTERFACE ${_lvslam_roscpp_includes})
endif()
target_link_libraries(lvslam_ros_deps INTERFACE PkgConfig::LVSLAM_ROSCPP)
message(STATUS "lvslam: ROS1 node ON (roscpp ${LVSLAM_ROSCPP_VERSION})")
