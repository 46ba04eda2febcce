#pragma once
// A small JSON reader for the files lvslam itself writes (stats.json, bench
// data): a report must refuse a truncated or corrupt file with one line that
// names it and the byte where it breaks, not inline it into a broken page.
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace lvslam::report {

class JsonValue {
 public:
  enum class Type { kNull, kBool, kNumber, kString, kArray, kObject };

  Type type = Type::kNull;
  bool boolean = false;
  double number = 0.0;
  std::string string;
  std::vector<JsonValue> array;
  std::map<std::string, JsonValue, std::less<>> object;

  bool isObject() const { return type == Type::kObject; }
  // The member `key` of an object, nullptr when absent or not an object.
  const JsonValue* find(std::string_view key) const;
};

// Parses `text`; throws lvslam::Error(name, "invalid JSON at byte N: why").
JsonValue parseJson(std::string_view text, const std::string& name);

// Reads and parses a file; the error names the file.
JsonValue readJsonFile(const std::string& path);

}  // namespace lvslam::report
