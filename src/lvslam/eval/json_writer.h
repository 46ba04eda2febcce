#pragma once
// A tiny JSON writer for reports: objects built field by field in insertion
// order, strings escaped, numbers in the shortest form that reads back to the
// same double, NaN and infinity written as null (JSON has neither).
#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace lvslam::eval {

std::string jsonString(std::string_view text);
std::string jsonNumber(double value);
std::string jsonArray(const std::vector<double>& values);

class JsonObject {
 public:
  JsonObject& addNumber(std::string_view key, double value);
  JsonObject& addCount(std::string_view key, std::size_t value);
  JsonObject& addString(std::string_view key, std::string_view value);
  // `json` must already be valid JSON (a nested object, an array, null).
  JsonObject& addRaw(std::string_view key, std::string json);
  std::string str() const;
  // The same text in pieces, none of them a copy of a member (a report's
  // data holds a run's whole stats.json).
  void write(const std::function<void(std::string_view)>& sink) const;

 private:
  std::vector<std::string> fields_;
};

}  // namespace lvslam::eval
