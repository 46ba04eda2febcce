// Fuzz harness: a LiDAR scan file (io/scan_file.h). The first byte gives the
// number of fields, the next ones each field's name (point_fields of
// sequence.yaml); the rest is the file.
#include <vector>

#include "fuzz_input.h"
#include "lvslam/io/scan_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const char* const kNames[] = {"x", "y", "z", "intensity", "time", "ring", "pad", "tiem"};
  if (size < 1) return 0;
  const std::size_t fields = 3 + data[0] % 6;
  if (size < 1 + fields) return 0;
  std::vector<std::string> point_fields;
  for (std::size_t i = 0; i < fields; ++i) point_fields.push_back(kNames[data[1 + i] % 8]);
  const std::string path = lvslam::fuzz::writeScratchFile(
      "0.bin", lvslam::fuzz::asText(data + 1 + fields, size - 1 - fields));
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    lvslam::LidarScan scan;
    (void)lvslam::readScanFile(path, lvslam::ScanLayout::fromFields(point_fields), scan);
  });
  return 0;
}
