#include "lvslam/io/png_check.h"

#include <array>
#include <cstdint>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam {

namespace {

constexpr std::string_view kSignature("\x89PNG\r\n\x1a\n", 8);

// CRC-32 as PNG defines it (ISO 3309, polynomial 0xEDB88320).
std::uint32_t crc32(std::string_view data) {
  static constexpr auto kTable = [] {
    std::array<std::uint32_t, 256> table{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      table[n] = c;
    }
    return table;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (const char byte : data) c = kTable[(c ^ static_cast<std::uint8_t>(byte)) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t bigEndian32(std::string_view bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (std::size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<std::uint8_t>(bytes[at + i]);
  return v;
}

}  // namespace

void checkPngChunks(std::string_view bytes, const std::string& path) {
  if (bytes.empty()) throw Error(path, "empty file (0 bytes)");
  if (bytes.substr(0, kSignature.size()) != kSignature) throw Error(path, "not a PNG file (no PNG signature)");
  std::size_t at = kSignature.size();
  while (at + 8 <= bytes.size()) {
    const std::size_t length = bigEndian32(bytes, at);
    const std::string type(bytes.substr(at + 4, 4));
    if (length > bytes.size() || at + 12 + length > bytes.size())
      throw Error(path, fmt::format("damaged PNG: the file ends at byte {} inside chunk '{}' of byte {} (truncated?)",
                                    bytes.size(), type, at));
    if (crc32(bytes.substr(at + 4, 4 + length)) != bigEndian32(bytes, at + 8 + length))
      throw Error(path, fmt::format("damaged PNG: chunk '{}' at byte {} ({} bytes) fails its CRC", type, at, length));
    if (type == "IEND") return;
    at += 12 + length;
  }
  throw Error(path, fmt::format("damaged PNG: the file ends at byte {} without an IEND chunk (truncated?)", bytes.size()));
}

}  // namespace lvslam
