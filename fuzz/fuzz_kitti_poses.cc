// Fuzz harness: KITTI odometry poses (io/tum.h, readKittiPoses). A line
// "--- times" splits the input into the pose file and its times file;
// without it the poses are read alone (stamped 0, 1, 2, ...).
#include "fuzz_input.h"
#include "lvslam/io/tum.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text = lvslam::fuzz::asText(data, size);
  constexpr std::string_view kSplit = "\n--- times\n";
  const std::size_t split = text.find(kSplit);
  const std::string poses = lvslam::fuzz::writeScratchFile("poses.txt", text.substr(0, split));
  const std::string times = split == std::string_view::npos
                                ? std::string()
                                : lvslam::fuzz::writeScratchFile("times.txt", text.substr(split + kSplit.size()));
  lvslam::fuzz::expectOnlyLvslamErrors([&] { (void)lvslam::readKittiPoses(poses, times); });
  return 0;
}
