#pragma once
// A section of the YAML configuration as one table: each key (a path below
// the section, "registration.max_iterations") bound to the member its value
// goes to. Every section reads, rejects and names its keys the same way, and
// the table is the one list of a section's keys (config/advanced.yaml shows
// each with its default; a test holds the two equal).
#include <cstddef>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "lvslam/core/yaml_config.h"

namespace lvslam {

class ConfigKeys {
 public:
  ConfigKeys& add(const std::string& key, double& value);
  ConfigKeys& add(const std::string& key, int& value);
  ConfigKeys& add(const std::string& key, bool& value);
  ConfigKeys& add(const std::string& key, std::size_t& value);  // an integer >= 0
  // One number that two members must share (it means the same in both).
  ConfigKeys& add(const std::string& key, double& value, double& same);
  // One of a few names.
  template <class Enum>
  ConfigKeys& add(const std::string& key, Enum& value, std::vector<std::pair<std::string, Enum>> names);
  // Every key of `keys` below `prefix` ("lidar": "lidar.preprocess.min_range").
  ConfigKeys& add(const std::string& prefix, ConfigKeys keys);

  // Reads the keys `node` holds, nested mappings for the parts of a key's
  // path; absent keys keep their value. An unknown key or a malformed value
  // throws lvslam::Error naming the file and the key's full path.
  void read(const YamlConfig& node) const;

  // Every key, in the order they were added.
  std::vector<std::string> keys() const;
  // A key's current value as YAML text (numbers in their shortest exact
  // form), so that two configurations can be compared key by key.
  std::string text(const std::string& key) const;

 private:
  struct Entry {
    std::string key;
    std::function<void(const YamlConfig&)> read;
    std::function<std::string()> text;
  };
  ConfigKeys& addEntry(Entry entry);
  void readMapping(const YamlConfig& node, const std::string& prefix) const;

  std::vector<Entry> entries_;
  std::map<std::string, std::size_t> index_;  // key -> entries_
  std::set<std::string> sections_;            // every proper prefix of a key ("registration")
};

template <class Enum>
ConfigKeys& ConfigKeys::add(const std::string& key, Enum& value, std::vector<std::pair<std::string, Enum>> names) {
  auto read = [&value, names](const YamlConfig& node) {
    const std::string name = node.asString();
    std::string all;
    for (const auto& [n, v] : names) {
      if (n == name) {
        value = v;
        return;
      }
      all += (all.empty() ? "'" : ", '") + n + "'";
    }
    node.fail("must be one of " + all + ", not '" + name + "'");
  };
  auto text = [&value, names] {
    for (const auto& [n, v] : names)
      if (v == value) return n;
    return std::string("?");
  };
  return addEntry({key, std::move(read), std::move(text)});
}

// Checks of the values a section ended up with, each naming the file it was
// read from and the key: ValueCheck check(file, "lidar");
// check(c.voxel_size > 0, "preprocess.voxel_size", "must be positive")
// throws lvslam::Error(file, "key 'lidar.preprocess.voxel_size': must be positive").
class ValueCheck {
 public:
  ValueCheck(std::string file, std::string section) : file_(std::move(file)), section_(std::move(section)) {}
  void operator()(bool ok, const std::string& key, const std::string& why) const;

 private:
  std::string file_, section_;
};

// Section `name` of `root` read onto the defaults of Config and checked
// (absent: the defaults). Config's namespace gives configKeys(Config&) and
// validate(const Config&, file).
template <class Config>
Config loadSection(const YamlConfig& root, const std::string& name) {
  Config config;
  if (const auto section = root.find(name)) {
    configKeys(config).read(*section);
    validate(config, section->file());
  }
  return config;
}

}  // namespace lvslam
