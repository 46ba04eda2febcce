// Fuzz harness: a sensor preset (io/sensor_preset.h, config/m2dgr.yaml's schema).
#include "fuzz_input.h"
#include "lvslam/io/sensor_preset.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lvslam::fuzz::writeScratchFile("preset.yaml", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors([&] { (void)lvslam::loadSensorPreset(path).calibration(); });
  return 0;
}
