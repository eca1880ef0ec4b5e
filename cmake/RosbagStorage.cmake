# Defines the imported target Scout::rosbag_storage for Debian's rosbag_storage
# (ROS 1 bag reading and writing) and the sensor_msgs / nav_msgs headers.
# Debian's own CMake config and pkg-config file pull in ament/pluginlib
# machinery that needs ROS 2 Python modules, so the libraries are found directly.
# The ROS 1 message headers use std::allocator<void>::rebind, which C++20
# removed: translation units including them must be compiled as C++17
# (see scout_ros1_sources()).
find_path(ROSBAG_STORAGE_INCLUDE_DIR rosbag/bag.h REQUIRED)
set(_scout_rosbag_extra_includes)
foreach(sub pluginlib class_loader rcpputils rcutils ament_index_cpp)
  if(IS_DIRECTORY /usr/include/${sub})
    list(APPEND _scout_rosbag_extra_includes /usr/include/${sub})
  endif()
endforeach()
find_path(SENSOR_MSGS_INCLUDE_DIR sensor_msgs/LaserScan.h REQUIRED)
find_path(NAV_MSGS_INCLUDE_DIR nav_msgs/Odometry.h REQUIRED)
set(_scout_rosbag_libs)
foreach(lib rosbag_storage roscpp_serialization rostime cpp_common console_bridge
            class_loader boost_filesystem)
  find_library(SCOUT_LIB_${lib} ${lib} REQUIRED)
  list(APPEND _scout_rosbag_libs ${SCOUT_LIB_${lib}})
endforeach()
add_library(Scout::rosbag_storage INTERFACE IMPORTED)
set_target_properties(Scout::rosbag_storage PROPERTIES
  INTERFACE_INCLUDE_DIRECTORIES
    "${ROSBAG_STORAGE_INCLUDE_DIR};${SENSOR_MSGS_INCLUDE_DIR};${NAV_MSGS_INCLUDE_DIR};${_scout_rosbag_extra_includes}"
  INTERFACE_LINK_LIBRARIES "${_scout_rosbag_libs}")

# scout_ros1_sources(FILES...): compiles these files as C++17 (ROS 1 headers).
# Call it from the CMakeLists.txt that declares the target: source properties
# are only seen by targets of the directory they are set in. CMake emits the
# target's -std=c++20 before per-source options, so this later -std=c++17
# wins (checked in compile_commands.json).
function(scout_ros1_sources)
  set_source_files_properties(${ARGN} PROPERTIES COMPILE_OPTIONS "-std=c++17")
endfunction()
