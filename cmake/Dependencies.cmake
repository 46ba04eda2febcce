# Every dependency comes from a Debian 12 package (scripts/install-deps.sh).
# Nothing is downloaded at build time.
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenCV 4.6 REQUIRED COMPONENTS core imgproc imgcodecs features2d calib3d)
find_package(yaml-cpp REQUIRED)
find_package(fmt REQUIRED)
find_package(spdlog REQUIRED)
find_package(CLI11 REQUIRED)
find_package(TBB REQUIRED)
find_package(nlohmann_json 3.11 REQUIRED)
find_package(Threads REQUIRED)

# nanoflann and tsl::robin_map are header-only; Debian ships their CMake configs.
find_package(nanoflann REQUIRED)
find_package(tsl-robin-map REQUIRED)

if(LVSLAM_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(LVSLAM_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
include(Rosbag)  # optional ROS1 bag component (LVSLAM_WITH_ROSBAG)
include(Ros)  # optional ROS1 node (LVSLAM_WITH_ROS), after the bag component it builds on
