#include "lvslam/core/config_keys.h"

#include <stdexcept>

#include <fmt/format.h>

#include "lvslam/core/error.h"

namespace lvslam {

ConfigKeys& ConfigKeys::addEntry(Entry entry) {
  if (index_.count(entry.key) || sections_.count(entry.key))
    throw std::logic_error("ConfigKeys: key '" + entry.key + "' added twice");
  for (std::size_t dot = entry.key.find('.'); dot != std::string::npos; dot = entry.key.find('.', dot + 1)) {
    const std::string section = entry.key.substr(0, dot);
    if (index_.count(section)) throw std::logic_error("ConfigKeys: key '" + section + "' is also a section");
    sections_.insert(section);
  }
  index_.emplace(entry.key, entries_.size());
  entries_.push_back(std::move(entry));
  return *this;
}

ConfigKeys& ConfigKeys::add(const std::string& key, double& value) {
  return addEntry({key, [&value](const YamlConfig& n) { value = n.asDouble(); },
                   [&value] { return fmt::format("{}", value); }});
}

ConfigKeys& ConfigKeys::add(const std::string& key, int& value) {
  return addEntry({key, [&value](const YamlConfig& n) { value = n.asInt(); },
                   [&value] { return std::to_string(value); }});
}

ConfigKeys& ConfigKeys::add(const std::string& key, bool& value) {
  return addEntry({key, [&value](const YamlConfig& n) { value = n.asBool(); },
                   [&value] { return std::string(value ? "true" : "false"); }});
}

ConfigKeys& ConfigKeys::add(const std::string& key, std::size_t& value) {
  auto read = [&value](const YamlConfig& n) {
    const int v = n.asInt();
    if (v < 0) n.fail("must not be negative");
    value = static_cast<std::size_t>(v);
  };
  return addEntry({key, std::move(read), [&value] { return std::to_string(value); }});
}

ConfigKeys& ConfigKeys::add(const std::string& key, double& value, double& same) {
  return addEntry({key, [&value, &same](const YamlConfig& n) { value = same = n.asDouble(); },
                   [&value] { return fmt::format("{}", value); }});
}

ConfigKeys& ConfigKeys::add(const std::string& prefix, ConfigKeys keys) {
  for (Entry& entry : keys.entries_) {
    entry.key = prefix + "." + entry.key;
    addEntry(std::move(entry));
  }
  return *this;
}

void ConfigKeys::read(const YamlConfig& node) const { readMapping(node, ""); }

void ConfigKeys::readMapping(const YamlConfig& node, const std::string& prefix) const {
  if (!node.node().IsMap()) node.fail("expected a mapping");
  for (const auto& item : node.node()) {
    const std::string name = item.first.Scalar();
    const std::string key = prefix.empty() ? name : prefix + "." + name;
    const YamlConfig child = node.child(name);
    if (const auto it = index_.find(key); it != index_.end()) {
      if (item.second.IsNull()) child.fail("no value");
      entries_[it->second].read(child);
    } else if (sections_.count(key)) {
      if (!item.second.IsNull()) readMapping(child, key);  // "section:" alone keeps every default
    } else {
      child.fail("unknown key (config/advanced.yaml lists every key)");
    }
  }
}

std::vector<std::string> ConfigKeys::keys() const {
  std::vector<std::string> out;
  for (const Entry& entry : entries_) out.push_back(entry.key);
  return out;
}

std::string ConfigKeys::text(const std::string& key) const {
  const auto it = index_.find(key);
  if (it == index_.end()) throw std::logic_error("ConfigKeys: no key '" + key + "'");
  return entries_[it->second].text();
}

void ValueCheck::operator()(bool ok, const std::string& key, const std::string& why) const {
  if (!ok) throw Error(file_, "key '" + section_ + "." + key + "': " + why);
}

}  // namespace lvslam
