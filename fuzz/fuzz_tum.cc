// Fuzz harness: a TUM trajectory file (io/tum.h, readTum).
#include "fuzz_input.h"
#include "lvslam/io/tum.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lvslam::fuzz::writeScratchFile("trajectory.tum", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors([&] { (void)lvslam::readTum(path); });
  return 0;
}
