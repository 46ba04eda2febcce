#include "lvslam/eval/json_writer.h"

#include <cmath>

#include <fmt/format.h>

namespace lvslam::eval {

std::string jsonString(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    switch (c) {
      case '"': out += "\\\""; break;
      case '\\': out += "\\\\"; break;
      case '\n': out += "\\n"; break;
      case '\r': out += "\\r"; break;
      case '\t': out += "\\t"; break;
      default:
        // Other control characters must be \u escapes; UTF-8 bytes pass through.
        if (static_cast<unsigned char>(c) < 0x20)
          out += fmt::format("\\u{:04x}", static_cast<unsigned>(static_cast<unsigned char>(c)));
        else
          out += c;
    }
  }
  return out + "\"";
}

std::string jsonNumber(double value) {
  if (!std::isfinite(value)) return "null";
  // fmt's default is the shortest representation that round-trips exactly.
  return fmt::format("{}", value);
}

std::string jsonArray(const std::vector<double>& values) {
  std::string out = "[";
  for (std::size_t i = 0; i < values.size(); ++i) out += (i ? ", " : "") + jsonNumber(values[i]);
  return out + "]";
}

JsonObject& JsonObject::addNumber(std::string_view key, double value) {
  return addRaw(key, jsonNumber(value));
}

JsonObject& JsonObject::addCount(std::string_view key, std::size_t value) {
  return addRaw(key, std::to_string(value));
}

JsonObject& JsonObject::addString(std::string_view key, std::string_view value) {
  return addRaw(key, jsonString(value));
}

JsonObject& JsonObject::addRaw(std::string_view key, std::string json) {
  fields_.push_back(jsonString(key) + ": " + std::move(json));
  return *this;
}

std::string JsonObject::str() const {
  std::string out;
  write([&out](std::string_view piece) { out += piece; });
  return out;
}

void JsonObject::write(const std::function<void(std::string_view)>& sink) const {
  sink("{");
  for (std::size_t i = 0; i < fields_.size(); ++i) {
    if (i) sink(", ");
    sink(fields_[i]);
  }
  sink("}");
}

}  // namespace lvslam::eval
