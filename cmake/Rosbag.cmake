# Optional ROS1 bag component (LVSLAM_WITH_ROSBAG): Debian 12's rosbag_storage
# (ROS Noetic's C++ bag library, packaged without catkin). Its CMake config and
# pkg-config file are incomplete on Debian (rosbag_storage.pc requires a
# pluginlib.pc that does not exist, and bag.h needs the include folders of the
# ROS 2 packages pluginlib, class_loader, rcpputils, rcutils and ament_index_cpp
# that Debian installs one level down, e.g. /usr/include/pluginlib/pluginlib/),
# so headers and libraries are found one by one here.
# Result: the INTERFACE target lvslam_rosbag_deps, only when the option is ON.
if(NOT LVSLAM_WITH_ROSBAG)
  return()
endif()

set(_lvslam_rosbag_missing "")
set(_lvslam_rosbag_include_dirs "")
set(_lvslam_rosbag_libraries "")

# <variable> <header> <path suffix under /usr/include ("." for none)> <Debian package>
function(_lvslam_rosbag_header var header suffix package)
  if(suffix STREQUAL ".")
    find_path(${var} NAMES ${header})
  else()
    find_path(${var} NAMES ${header} PATH_SUFFIXES ${suffix})
  endif()
  if(${var})
    set(_lvslam_rosbag_include_dirs ${_lvslam_rosbag_include_dirs} ${${var}} PARENT_SCOPE)
  else()
    set(_lvslam_rosbag_missing ${_lvslam_rosbag_missing} "${header} (${package})" PARENT_SCOPE)
  endif()
endfunction()

function(_lvslam_rosbag_library var name package)
  find_library(${var} NAMES ${name})
  if(${var})
    set(_lvslam_rosbag_libraries ${_lvslam_rosbag_libraries} ${${var}} PARENT_SCOPE)
  else()
    set(_lvslam_rosbag_missing ${_lvslam_rosbag_missing} "lib${name} (${package})" PARENT_SCOPE)
  endif()
endfunction()

_lvslam_rosbag_header(LVSLAM_ROSBAG_INCLUDE rosbag/bag.h . librosbag-storage-dev)
_lvslam_rosbag_header(LVSLAM_ROSCPP_CORE_INCLUDE ros/serialization.h . libroscpp-core-dev)
_lvslam_rosbag_header(LVSLAM_SENSOR_MSGS_INCLUDE sensor_msgs/PointCloud2.h . libsensor-msgs-dev)
_lvslam_rosbag_header(LVSLAM_ROSLZ4_INCLUDE roslz4/lz4s.h . libroslz4-dev)
_lvslam_rosbag_header(LVSLAM_BZIP2_INCLUDE bzlib.h . libbz2-dev)
_lvslam_rosbag_header(LVSLAM_PLUGINLIB_INCLUDE pluginlib/class_loader.hpp pluginlib pluginlib-dev)
_lvslam_rosbag_header(LVSLAM_CLASS_LOADER_INCLUDE class_loader/class_loader.hpp class_loader libclass-loader-dev)
_lvslam_rosbag_header(LVSLAM_RCPPUTILS_INCLUDE rcpputils/shared_library.hpp rcpputils librcpputils-dev)
_lvslam_rosbag_header(LVSLAM_RCUTILS_INCLUDE rcutils/allocator.h rcutils librcutils-dev)
_lvslam_rosbag_header(LVSLAM_AMENT_INDEX_INCLUDE ament_index_cpp/get_resource.hpp ament_index_cpp libament-index-cpp-dev)

_lvslam_rosbag_library(LVSLAM_ROSBAG_STORAGE_LIBRARY rosbag_storage librosbag-storage-dev)
_lvslam_rosbag_library(LVSLAM_ROSCPP_SERIALIZATION_LIBRARY roscpp_serialization libroscpp-core-dev)
_lvslam_rosbag_library(LVSLAM_ROSTIME_LIBRARY rostime libroscpp-core-dev)
_lvslam_rosbag_library(LVSLAM_CPP_COMMON_LIBRARY cpp_common libroscpp-core-dev)
# rosbag::Bag's templates log through console_bridge.
_lvslam_rosbag_library(LVSLAM_CONSOLE_BRIDGE_LIBRARY console_bridge libconsole-bridge-dev)
_lvslam_rosbag_library(LVSLAM_ROSLZ4_LIBRARY roslz4 libroslz4-dev)
_lvslam_rosbag_library(LVSLAM_BZIP2_LIBRARY bz2 libbz2-dev)

if(_lvslam_rosbag_missing)
  list(JOIN _lvslam_rosbag_missing "\n  " _missing_text)
  message(FATAL_ERROR
    "LVSLAM_WITH_ROSBAG is ON but these ROS1 bag dependencies are missing:\n  ${_missing_text}\n"
    "Install them with scripts/install-deps.sh, or configure with -DLVSLAM_WITH_ROSBAG=OFF "
    "to build without ROS bag support.")
endif()

list(REMOVE_DUPLICATES _lvslam_rosbag_include_dirs)
add_library(lvslam_rosbag_deps INTERFACE)
# SYSTEM: the ROS headers are not -Wall -Wextra clean and are not ours.
target_include_directories(lvslam_rosbag_deps SYSTEM INTERFACE ${_lvslam_rosbag_include_dirs})
target_link_libraries(lvslam_rosbag_deps INTERFACE ${_lvslam_rosbag_libraries})
message(STATUS "lvslam: ROS1 bag support ON (rosbag_storage: ${LVSLAM_ROSBAG_STORAGE_LIBRARY})")
