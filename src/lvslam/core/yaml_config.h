#pragma once
// A YAML node that knows where it came from, so that every error names the
// file and the key path ("sequence.yaml: key 'camera.intrinsics': ...").
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace lvslam {

class YamlConfig {
 public:
  // Throws lvslam::Error naming the file when it is missing or malformed.
  static YamlConfig loadFile(const std::string& path);
  static YamlConfig loadString(const std::string& text, const std::string& source_name);

  bool has(const std::string& key) const;
  // Required child: throws "missing required key" naming the full key path.
  YamlConfig at(const std::string& key) const;
  std::optional<YamlConfig> find(const std::string& key) const;
  // The child whatever it holds (a null node when absent): for error messages.
  YamlConfig child(const std::string& key) const;

  std::string asString() const;
  double asDouble() const;         // finite numbers only
  int asInt() const;
  bool asBool() const;
  std::vector<double> asDoubles() const;  // a sequence of finite numbers
  std::vector<std::string> asStrings() const;

  // Optional scalars with a default.
  double getDouble(const std::string& key, double fallback) const;
  int getInt(const std::string& key, int fallback) const;
  bool getBool(const std::string& key, bool fallback) const;
  std::string getString(const std::string& key, const std::string& fallback) const;

  // A mapping whose keys are all among `known`, else fail() naming the first
  // unknown key (catches typos that would silently keep a default).
  void requireKnownKeys(const std::vector<std::string>& known) const;

  // Throws lvslam::Error(file, "key '<path>': <why>").
  [[noreturn]] void fail(const std::string& why) const;

  const std::string& file() const { return file_; }
  const std::string& keyPath() const { return key_path_; }
  const YAML::Node& node() const { return node_; }

 private:
  YamlConfig(YAML::Node node, std::string file, std::string key_path);
  std::string childPath(const std::string& key) const;

  YAML::Node node_;
  std::string file_;
  std::string key_path_;
};

}  // namespace lvslam
