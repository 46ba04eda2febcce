// Fuzz harness: an image file of a sequence folder (io/image_file.h): the PNG
// chunk check, then OpenCV's decoder (libpng).
#include "fuzz_input.h"
#include "lvslam/io/image_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lvslam::fuzz::writeScratchFile("0.png", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors([&] { (void)lvslam::readImageFile(path); });
  return 0;
}
