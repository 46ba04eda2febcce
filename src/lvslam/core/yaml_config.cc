#include "lvslam/core/yaml_config.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "lvslam/core/error.h"
#include "lvslam/core/file_access.h"

namespace lvslam {

namespace {

// Keys are names: a mapping or a list as a key ("{a: 1}: 2", "? [a, b]")
// would surface later as yaml-cpp's "bad conversion" with no file named, so
// the whole document is checked once when it is loaded.
void requireScalarKeys(const YAML::Node& node, const std::string& file, const std::string& key_path) {
  if (node.IsSequence()) {
    for (std::size_t i = 0; i < node.size(); ++i)
      requireScalarKeys(node[i], file, key_path + "[" + std::to_string(i) + "]");
    return;
  }
  if (!node.IsMap()) return;
  for (const auto& item : node) {
    if (!item.first.IsScalar())
      throw Error(file + ":" + std::to_string(item.first.Mark().line + 1),
                  "key '" + (key_path.empty() ? std::string("<root>") : key_path) +
                      "': a mapping key must be a plain name, not a list or a mapping");
    const std::string key = item.first.Scalar();
    requireScalarKeys(item.second, file, key_path.empty() ? key : key_path + "." + key);
  }
}

}  // namespace

YamlConfig::YamlConfig(YAML::Node node, std::string file, std::string key_path)
    : node_(std::move(node)), file_(std::move(file)), key_path_(std::move(key_path)) {}

YamlConfig YamlConfig::loadFile(const std::string& path) {
  std::ifstream in = openInputFile(path);
  std::ostringstream text;
  text << in.rdbuf();
  return loadString(text.str(), path);
}

YamlConfig YamlConfig::loadString(const std::string& text, const std::string& source_name) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw Error(source_name, "malformed YAML at line " + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (!root.IsMap()) throw Error(source_name, "malformed YAML: the top level is not a mapping");
  requireScalarKeys(root, source_name, "");
  return YamlConfig(root, source_name, "");
}

std::string YamlConfig::childPath(const std::string& key) const {
  return key_path_.empty() ? key : key_path_ + "." + key;
}

void YamlConfig::requireKnownKeys(const std::vector<std::string>& known) const {
  if (!node_.IsMap()) fail("expected a mapping");
  for (const auto& item : node_) {
    const std::string key = item.first.as<std::string>();
    if (std::find(known.begin(), known.end(), key) == known.end()) fail("unknown key '" + key + "'");
  }
}

void YamlConfig::fail(const std::string& why) const {
  throw Error(file_, "key '" + (key_path_.empty() ? std::string("<root>") : key_path_) + "': " + why);
}

bool YamlConfig::has(const std::string& key) const {
  return node_.IsMap() && node_[key].IsDefined() && !node_[key].IsNull();
}

YamlConfig YamlConfig::at(const std::string& key) const {
  if (!has(key)) YamlConfig(node_, file_, childPath(key)).fail("missing required key");
  return YamlConfig(node_[key], file_, childPath(key));
}

std::optional<YamlConfig> YamlConfig::find(const std::string& key) const {
  if (!has(key)) return std::nullopt;
  return YamlConfig(node_[key], file_, childPath(key));
}

YamlConfig YamlConfig::child(const std::string& key) const {
  return YamlConfig(node_.IsMap() ? node_[key] : YAML::Node(), file_, childPath(key));
}

std::string YamlConfig::asString() const {
  if (!node_.IsScalar()) fail("expected a scalar");
  return node_.Scalar();
}

double YamlConfig::asDouble() const {
  if (!node_.IsScalar()) fail("expected a number");
  double v = 0.0;
  if (!YAML::convert<double>::decode(node_, v) || !std::isfinite(v))
    fail("malformed number '" + node_.Scalar() + "'");
  return v;
}

int YamlConfig::asInt() const {
  if (!node_.IsScalar()) fail("expected an integer");
  int v = 0;
  if (!YAML::convert<int>::decode(node_, v)) fail("malformed integer '" + node_.Scalar() + "'");
  return v;
}

bool YamlConfig::asBool() const {
  if (!node_.IsScalar()) fail("expected true or false");
  bool v = false;
  if (!YAML::convert<bool>::decode(node_, v)) fail("malformed boolean '" + node_.Scalar() + "'");
  return v;
}

std::vector<double> YamlConfig::asDoubles() const {
  if (!node_.IsSequence()) fail("expected a list of numbers");
  std::vector<double> out;
  for (std::size_t i = 0; i < node_.size(); ++i)
    out.push_back(YamlConfig(node_[i], file_, key_path_ + "[" + std::to_string(i) + "]").asDouble());
  return out;
}

std::vector<std::string> YamlConfig::asStrings() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<std::string> out;
  for (std::size_t i = 0; i < node_.size(); ++i)
    out.push_back(YamlConfig(node_[i], file_, key_path_ + "[" + std::to_string(i) + "]").asString());
  return out;
}

double YamlConfig::getDouble(const std::string& key, double fallback) const {
  return has(key) ? at(key).asDouble() : fallback;
}
int YamlConfig::getInt(const std::string& key, int fallback) const {
  return has(key) ? at(key).asInt() : fallback;
}
bool YamlConfig::getBool(const std::string& key, bool fallback) const {
  return has(key) ? at(key).asBool() : fallback;
}
std::string YamlConfig::getString(const std::string& key, const std::string& fallback) const {
  return has(key) ? at(key).asString() : fallback;
}

}  // namespace lvslam
