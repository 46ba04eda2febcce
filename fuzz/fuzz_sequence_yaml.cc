// Fuzz harness: sequence.yaml (io/sequence_info.h, readSequenceInfo).
#include "fuzz_input.h"
#include "lvslam/io/sequence_info.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lvslam::fuzz::writeScratchFile("sequence.yaml", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors([&] { (void)lvslam::readSequenceInfo(path).calibration(); });
  return 0;
}
