// Fuzz harness: the JSON reader of reports (report/json_reader.h: stats.json,
// bench data).
#include "fuzz_input.h"
#include "lvslam/report/json_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  lvslam::fuzz::expectOnlyLvslamErrors([&] {
    const nlohmann::json document = lvslam::report::parseJson(lvslam::fuzz::asText(data, size), "stats.json");
    if (const nlohmann::json* summary = lvslam::report::findMember(document, "summary"))
      (void)lvslam::report::findMember(*summary, "accuracy");
  });
  return 0;
}
