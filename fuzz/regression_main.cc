// Runs a fuzz harness's LLVMFuzzerTestOneInput on files, without libFuzzer:
// how the normal (gcc) build replays fuzz/regressions/NAME and
// fuzz/corpus/NAME in ctest. A crash, a sanitizer report or an uncaught
// exception other than lvslam::Error fails the test, as it would fail the fuzzer;
// so does an allocation beyond 1 GiB of address space (std::bad_alloc: the
// fuzzer's memory limit; not under AddressSanitizer, which reserves terabytes)
// and a hang (ctest's TIMEOUT).
#include <sys/resource.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

#if defined(__SANITIZE_ADDRESS__)
#define LVSLAM_REGRESSION_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define LVSLAM_REGRESSION_UNDER_ASAN 1
#endif
#endif

namespace {

std::vector<std::filesystem::path> inputsOf(const std::filesystem::path& arg) {
  std::vector<std::filesystem::path> files;
  if (std::filesystem::is_directory(arg)) {
    for (const auto& entry : std::filesystem::directory_iterator(arg))
      if (entry.is_regular_file()) files.push_back(entry.path());
    std::sort(files.begin(), files.end());
  } else {
    files.push_back(arg);
  }
  return files;
}

}  // namespace

int main(int argc, char** argv) {
#ifndef LVSLAM_REGRESSION_UNDER_ASAN
  constexpr rlim_t kAddressSpace = rlim_t{1} << 30;
  const rlimit limit{kAddressSpace, kAddressSpace};
  setrlimit(RLIMIT_AS, &limit);
#endif
  std::size_t ran = 0;
  for (int i = 1; i < argc; ++i) {
    if (!std::filesystem::exists(argv[i])) {
      std::cerr << argv[i] << ": no such file or folder\n";
      return 2;
    }
    for (const auto& file : inputsOf(argv[i])) {
      std::ifstream in(file, std::ios::binary);
      const std::vector<std::uint8_t> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
      std::cout << "input " << file.string() << " (" << bytes.size() << " bytes)" << std::endl;
      LLVMFuzzerTestOneInput(bytes.data(), bytes.size());
      ++ran;
    }
  }
  std::cout << ran << " inputs, no finding\n";
  return ran > 0 ? 0 : 1;
}
