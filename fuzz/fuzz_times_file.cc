// Fuzz harness: camera/times.txt and lidar/times.txt (io/times_file.h). The
// files "0.png", "1.png" and "0.bin" exist beside it, so lines naming them get
// past the existence check into the ordering checks.
#include "fuzz_input.h"
#include "lvslam/io/times_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const bool files_made = [] {
    for (const char* name : {"0.png", "1.png", "0.bin"}) lvslam::fuzz::writeScratchFile(name, "");
    return true;
  }();
  (void)files_made;
  const std::string path = lvslam::fuzz::writeScratchFile("times.txt", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    const auto files = lvslam::readTimesFile(path);
    (void)lvslam::findTimeJumps(files);
  });
  return 0;
}
