// Fuzz harness: the map a run saves and another reads (system/saved_map.h,
// lvslam run --map-in): a binary file from the user's disk. The first byte
// chooses: even, the rest is the file with its header's CRC-32 made to match
// its payload (so that mutations reach the fields' decoding and checks);
// odd, the rest as it is (the CRC's own check).
#include <cstring>

#include <zlib.h>

#include "fuzz_input.h"
#include "lvslam/system/saved_map.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  std::string bytes(lvslam::fuzz::asText(data + 1, size - 1));
  constexpr std::size_t kHeader = 11 + 4 + 8 + 4;  // tag, version, size, CRC
  if (data[0] % 2 == 0 && bytes.size() >= kHeader) {
    const auto crc = static_cast<std::uint32_t>(
        crc32_z(0L, reinterpret_cast<const Bytef*>(bytes.data() + kHeader), bytes.size() - kHeader));
    std::memcpy(bytes.data() + kHeader - 4, &crc, sizeof(crc));
  }
  const std::string path = lvslam::fuzz::writeScratchFile("room.lvmap", bytes);
  lvslam::fuzz::expectOnlyLvslamErrors([&] { (void)lvslam::system::readSavedMap(path); });
  return 0;
}
