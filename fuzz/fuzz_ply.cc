// Fuzz harness: map.ply and lines.ply read back for reports (io/ply_reader.h);
// the first byte chooses which reader.
#include "fuzz_input.h"
#include "lvslam/io/ply_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string path = lvslam::fuzz::writeScratchFile("map.ply", lvslam::fuzz::asText(data + 1, size - 1));
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    if (data[0] % 2 == 0)
      (void)lvslam::readPointCloudPly(path);
    else
      (void)lvslam::readLineSegmentsPly(path);
  });
  return 0;
}
