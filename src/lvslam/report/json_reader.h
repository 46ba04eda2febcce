#pragma once
// Reading the JSON files lvslam itself writes (stats.json, bench data) through
// nlohmann::json: a report must refuse a truncated or corrupt file with one
// line that names it and the byte where it breaks, not inline it into a
// broken page.
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace lvslam::report {

// Parses `text`; throws lvslam::Error(name, "invalid JSON at byte N: why")
// for anything that is not one whole JSON document (also a bad \u escape or
// invalid UTF-8 inside a string). `keep`, when given, is nlohmann's parser
// callback: what it returns false for is checked but not kept.
nlohmann::json parseJson(std::string_view text, const std::string& name,
                         const nlohmann::json::parser_callback_t& keep = nullptr);

// Reads and parses a file; the error names the file.
nlohmann::json readJsonFile(const std::string& path);

// The member `key` of `object`, nullptr when absent or `object` is not an object.
const nlohmann::json* findMember(const nlohmann::json& object, std::string_view key);

}  // namespace lvslam::report
