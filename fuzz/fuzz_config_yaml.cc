// Fuzz harness: the --config YAML of lvslam run (system/system_config.h).
#include "fuzz_input.h"
#include "lvslam/system/system_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = lvslam::fuzz::writeScratchFile("config.yaml", lvslam::fuzz::asText(data, size));
  lvslam::fuzz::expectOnlyLvslamErrors(
      [&] { (void)lvslam::system::loadSystemConfig(lvslam::YamlConfig::loadFile(path)); });
  return 0;
}
