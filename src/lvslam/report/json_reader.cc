#include "lvslam/report/json_reader.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam::report {

namespace {

// nlohmann's what() is "[json.exception.parse_error.101] parse error at line
// 1, column 27: <why>"; the file's name and the byte say where, so only <why>
// is kept.
std::string reasonOf(const std::string& what) {
  const std::size_t colon = what.find(": ");
  return colon == std::string::npos ? what : what.substr(colon + 2);
}

}  // namespace

nlohmann::json parseJson(std::string_view text, const std::string& name,
                         const nlohmann::json::parser_callback_t& keep) {
  try {
    return nlohmann::json::parse(text.begin(), text.end(), keep);
  } catch (const nlohmann::json::parse_error& e) {
    // e.byte counts from 1 and lies one past the text when the text ended
    // too early: reported as the byte (from 0) where reading stopped.
    const std::size_t byte = std::min<std::size_t>(e.byte == 0 ? 0 : e.byte - 1, text.size());
    const std::string truncated = byte >= text.size() ? "the file ends early (truncated?): " : "";
    throw Error(name, fmt::format("invalid JSON at byte {}: {}{}", byte, truncated, reasonOf(e.what())));
  } catch (const nlohmann::json::exception& e) {
    throw Error(name, "invalid JSON: " + reasonOf(e.what()));
  }
}

nlohmann::json readJsonFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot read the file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return parseJson(buffer.str(), path);
}

const nlohmann::json* findMember(const nlohmann::json& object, std::string_view key) {
  if (!object.is_object()) return nullptr;
  const auto it = object.find(key);
  return it == object.end() ? nullptr : &*it;
}

}  // namespace lvslam::report
