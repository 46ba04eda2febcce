// Fuzz harness: a ROS1 bag read record by record (io/rosbag_recovery.h: record
// headers, connection records, chunks none / lz4 / bz2, messages), the reader
// of bags whose index is missing or damaged.
#include "fuzz_input.h"
#include "lvslam/io/rosbag_recovery.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lvslam::fuzz::writeScratchFile("recording.bag", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    lvslam::BagRecordScanner scanner(path);
    while (scanner.next()) {
    }
    (void)scanner.connections();
  });
  return 0;
}
