#pragma once
// What every fuzz harness shares: the parsers under test read files, so the
// input is written to a scratch folder of this process first; bad input must
// end as lvslam::Error (expected, not a finding); anything else escapes to
// libFuzzer (or to regression_main.cc) as the finding it is.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

#include <spdlog/spdlog.h>

#include "lvslam/core/error.h"

namespace lvslam::fuzz {

// A folder of this process's own, removed when the process ends normally.
class ScratchFolder {
 public:
  ScratchFolder() : path_(base() / ("lvslam-fuzz-" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path_);
  }
  ~ScratchFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  // In memory when the system has /dev/shm: a file truncated and rewritten
  // millions of times on ext4 waits for the disk each time (auto_da_alloc).
  static std::filesystem::path base() {
    std::error_code ec;
    return std::filesystem::is_directory("/dev/shm", ec) ? std::filesystem::path("/dev/shm")
                                                         : std::filesystem::temp_directory_path();
  }

  std::filesystem::path path_;
};

inline const std::filesystem::path& scratchFolder() {
  static const ScratchFolder folder;  // one per process: libFuzzer calls the harness millions of times
  return folder.path();
}

// Writes `bytes` to the scratch folder as `name` and returns its path.
inline std::string writeScratchFile(const std::string& name, std::string_view bytes) {
  const std::filesystem::path path = scratchFolder() / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return path.string();
}

inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `parse`, taking lvslam::Error as the expected answer to bad input.
// Warnings are silenced: they are answers too, and printing them would slow
// the fuzzer a hundredfold.
template <typename Parse>
void expectOnlyLvslamErrors(Parse&& parse) {
  spdlog::set_level(spdlog::level::off);
  try {
    parse();
  } catch (const lvslam::Error&) {
  }
}

}  // namespace lvslam::fuzz
