#include "lvslam/core/config_keys.h"

#include <stdexcept>

#include <gtest/gtest.h>

#include "support/temp_dir.h"

namespace lvslam {
namespace {

using testing::errorMessageOf;

enum class Colour { kRed, kBlue };

struct Settings {
  double size = 1.5;
  int count = 3;
  bool on = true;
  std::size_t slots = 4;
  double shared = 0.5, copy = 0.5;
  Colour colour = Colour::kRed;
};

ConfigKeys keysOf(Settings& s) {
  ConfigKeys keys;
  keys.add("size", s.size)
      .add("inner.count", s.count)
      .add("inner.deeper.on", s.on)
      .add("slots", s.slots)
      .add("shared", s.shared, s.copy)
      .add("colour", s.colour, {{"red", Colour::kRed}, {"blue", Colour::kBlue}});
  return keys;
}

Settings read(const std::string& text) {
  Settings s;
  keysOf(s).read(YamlConfig::loadString(text, "k.yaml"));
  return s;
}

TEST(ConfigKeys, ReadsNestedKeysAndKeepsAbsentOnes) {
  const Settings s = read("inner:\n  count: 7\n  deeper: {on: false}\nshared: 2\ncolour: blue\n");
  EXPECT_EQ(s.count, 7);
  EXPECT_FALSE(s.on);
  EXPECT_EQ(s.colour, Colour::kBlue);
  EXPECT_DOUBLE_EQ(s.shared, 2.0);
  EXPECT_DOUBLE_EQ(s.copy, 2.0);
  EXPECT_DOUBLE_EQ(s.size, 1.5);
  EXPECT_EQ(s.slots, 4u);
  EXPECT_EQ(read("inner:\n").count, 3);  // a section alone keeps its defaults
}

TEST(ConfigKeys, ErrorsNameTheFileAndTheFullKey) {
  EXPECT_EQ(errorMessageOf([] { read("inner:\n  cont: 1\n"); }),
            "k.yaml: key 'inner.cont': unknown key (config/advanced.yaml lists every key)");
  EXPECT_EQ(errorMessageOf([] { read("inner: 3\n"); }), "k.yaml: key 'inner': expected a mapping");
  EXPECT_EQ(errorMessageOf([] { read("size:\n"); }), "k.yaml: key 'size': no value");
  EXPECT_EQ(errorMessageOf([] { read("size: big\n"); }), "k.yaml: key 'size': malformed number 'big'");
  EXPECT_EQ(errorMessageOf([] { read("slots: -1\n"); }), "k.yaml: key 'slots': must not be negative");
  EXPECT_EQ(errorMessageOf([] { read("colour: green\n"); }),
            "k.yaml: key 'colour': must be one of 'red', 'blue', not 'green'");
  EXPECT_EQ(errorMessageOf([] { read("inner: {deeper: {on: 2}}\n"); }),
            "k.yaml: key 'inner.deeper.on': malformed boolean '2'");
}

TEST(ConfigKeys, PrefixedTablesAndTheirValuesAsText) {
  Settings s;
  s.size = 0.1;
  ConfigKeys all;
  all.add("a", keysOf(s));
  EXPECT_EQ(all.keys().front(), "a.size");
  EXPECT_EQ(all.text("a.size"), "0.1");
  EXPECT_EQ(all.text("a.inner.deeper.on"), "true");
  EXPECT_EQ(all.text("a.colour"), "red");
  all.read(YamlConfig::loadString("a: {slots: 9}\n", "k.yaml"));
  EXPECT_EQ(all.text("a.slots"), "9");
}

TEST(ConfigKeys, ATableWithAKeyTwiceIsAMistakeOfTheCode) {
  double x = 0, y = 0;
  ConfigKeys keys;
  keys.add("a.b", x);
  EXPECT_THROW(keys.add("a.b", y), std::logic_error);
  EXPECT_THROW(keys.add("a", y), std::logic_error);
  EXPECT_THROW(keys.add("a.b.c", y), std::logic_error);
}

}  // namespace
}  // namespace lvslam
