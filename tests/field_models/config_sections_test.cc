#include "field_models/config_sections.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

namespace houghloc {
namespace {

enum class Mode { kFast, kExact };

struct Inner {
  double scale = 1.5;
  Mode mode = Mode::kFast;
};

struct Outer {
  int count = 3;
  std::size_t limit = 100;
  bool enabled = true;
  float gain = 0.25f;
  Inner inner;
};

ConfigSection sectionOf(Outer& o) {
  return {{configMember("count", &o.count), configMember("limit", &o.limit),
           configMember("enabled", &o.enabled), configMember("gain", &o.gain)},
          {{"inner",
            {{configMember("scale", &o.inner.scale),
              configEnumMember("mode", &o.inner.mode,
                               {{"fast", Mode::kFast}, {"exact", Mode::kExact}})}}}}};
}

Outer readYaml(const std::string& body) {
  cv::FileStorage storage("%YAML:1.0\n---\n" + body,
                          cv::FileStorage::READ | cv::FileStorage::MEMORY);
  Outer out;
  readConfigSection(storage.root()["outer"], sectionOf(out), "test.yaml: outer");
  return out;
}

std::string writeYaml(Outer o) {
  cv::FileStorage storage(".yaml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY);
  writeConfigSection(storage, "outer", sectionOf(o));
  return storage.releaseAndGetString();
}

std::string sectionErrorOf(const std::string& body) {
  try {
    readYaml(body);
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

TEST(ConfigSections, ReadsNestedMembersAndKeepsDefaults) {
  const Outer o = readYaml("outer:\n  count: 7\n  gain: 2\n  inner:\n    mode: exact\n");
  EXPECT_EQ(o.count, 7);
  EXPECT_FLOAT_EQ(o.gain, 2.0f);  // an integer is a valid real
  EXPECT_EQ(o.inner.mode, Mode::kExact);
  EXPECT_EQ(o.limit, 100u);
  EXPECT_TRUE(o.enabled);
  EXPECT_DOUBLE_EQ(o.inner.scale, 1.5);
  const Outer missing = readYaml("other: 1\n");
  EXPECT_EQ(missing.count, 3);
}

TEST(ConfigSections, ReadsTrueAndFalseAsFlags) {
  EXPECT_FALSE(readYaml("outer:\n  enabled: false\n").enabled);
  EXPECT_FALSE(readYaml("outer:\n  enabled: False\n").enabled);
  EXPECT_FALSE(readYaml("outer:\n  enabled: 0\n").enabled);
  EXPECT_TRUE(readYaml("outer:\n  enabled: true\n").enabled);
  EXPECT_TRUE(readYaml("outer:\n  enabled: TRUE\n").enabled);
}

TEST(ConfigSections, RoundTripsEveryMember) {
  Outer o;
  o.count = -4;
  o.limit = 123456;
  o.enabled = false;
  o.gain = 0.125f;
  o.inner.scale = 0.1234567890123456;
  o.inner.mode = Mode::kExact;
  const std::string text = writeYaml(o);
  cv::FileStorage storage(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
  Outer back;
  readConfigSection(storage.root()["outer"], sectionOf(back), "mem");
  EXPECT_EQ(back.count, -4);
  EXPECT_EQ(back.limit, 123456u);
  EXPECT_FALSE(back.enabled);
  EXPECT_FLOAT_EQ(back.gain, 0.125f);
  EXPECT_DOUBLE_EQ(back.inner.scale, 0.1234567890123456);
  EXPECT_EQ(back.inner.mode, Mode::kExact);
  EXPECT_EQ(writeYaml(back), text);
}

TEST(ConfigSections, ErrorsNameSourceAndKey) {
  EXPECT_EQ(sectionErrorOf("outer:\n  inner:\n    colour: 1\n"),
            "test.yaml: outer.inner.colour: unknown key");
  EXPECT_EQ(sectionErrorOf("outer:\n  count: many\n"), "test.yaml: outer.count: expected a number");
  EXPECT_EQ(sectionErrorOf("outer:\n  count: 2.5\n"),
            "test.yaml: outer.count: expected an integer");
  EXPECT_EQ(sectionErrorOf("outer:\n  limit: -1\n"), "test.yaml: outer.limit: out of range");
  EXPECT_EQ(sectionErrorOf("outer:\n  enabled: 2\n"),
            "test.yaml: outer.enabled: expected 0, 1, true or false");
  EXPECT_EQ(sectionErrorOf("outer:\n  enabled: yes please\n"),
            "test.yaml: outer.enabled: expected 0, 1, true or false");
  EXPECT_EQ(sectionErrorOf("outer:\n  inner:\n    mode: slow\n"),
            "test.yaml: outer.inner.mode: expected one of fast, exact");
  EXPECT_EQ(sectionErrorOf("outer:\n  inner: 3\n"), "test.yaml: outer.inner: expected a map");
  EXPECT_EQ(sectionErrorOf("outer: [1, 2]\n"), "test.yaml: outer: expected a map");
}

}  // namespace
}  // namespace houghloc
