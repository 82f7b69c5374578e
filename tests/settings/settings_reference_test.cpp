// The settings reference (docs/settings.md, `slamkit settings`) and the field list it is made
// from: every struct member is visited, and every visited key can be set from YAML.
#include "settings/settings_reference.h"

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include "settings/aggregate_arity.h"
#include "settings/settings_fields.h"
#include "settings/settings_yaml.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// "line N: committed '...', generated '...'" for the first line that differs.
std::string first_difference(const std::string& committed, const std::string& generated) {
  const std::vector<std::string> a = lines_of(committed), b = lines_of(generated);
  for (size_t i = 0; i < std::max(a.size(), b.size()); ++i) {
    const std::string left = i < a.size() ? a[i] : "(end of file)";
    const std::string right = i < b.size() ? b[i] : "(end of file)";
    if (left != right)
      return "line " + std::to_string(i + 1) + ":\n  committed: " + left +
             "\n  generated: " + right;
  }
  return "the same lines, different line ends";
}

TEST(SettingsReference, CommittedDocIsTheGeneratorsOutput) {
  const fs::path doc = fs::path(SLAMKIT_SOURCE_DIR) / "docs" / "settings.md";
  const std::string committed = test::read_text(doc);
  const std::string generated = settings_reference_markdown();
  EXPECT_TRUE(committed == generated)
      << doc.string() << " is out of date with the settings (a default in lib/core/settings or a "
      << "range or note in lib/io/settings_fields.h changed); build slamkit and regenerate it:\n  "
      << SLAMKIT_BINARY << " settings --markdown > " << doc.string() << "\nfirst difference, "
      << first_difference(committed, generated);
}

TEST(SettingsReference, HasARowPerFieldInATablePerSection) {
  const std::string markdown = settings_reference_markdown();
  EXPECT_NE(markdown.find("| `tracking.ransac.seed` | `42` | 0..4294967295 | slamkit |"),
            std::string::npos);
  EXPECT_NE(markdown.find("| `orb.fast_type` | `fast9` | fast9, fast12 | slamkit |"),
            std::string::npos);
  EXPECT_NE(markdown.find("| `orb.scale_factor` | `1.2` | 1 (excluded)..2 | paper |"),
            std::string::npos);
  EXPECT_NE(markdown.find("\n## optimization\n"), std::string::npos);
  EXPECT_NE(markdown.find("- `optimization.local_ba`: local BA at each new keyframe\n"),
            std::string::npos);
}

// A valid value other than `value` for a field (nullopt when its range holds no other).
template <class T>
std::optional<T> other_value(T value, const Range& range) {
  const T half_way_down = range.lo > -kNoLimit ? T((range.lo + double(value)) / 2) : T(value / 2);
  for (const T candidate : {T(value + 1), T(value - 1), T(value / 2), half_way_down})
    if (candidate != value && in_range(double(candidate), range)) return candidate;
  return std::nullopt;
}

// One field set to another valid value: the YAML document that sets it, and the line the
// settings writer then prints for it.
struct Probe {
  std::string key;
  std::string document;
  std::string written_line;
};

// Sets every field of the settings it walks to another valid value, noting a Probe for each.
class ValueChanger {
 public:
  template <class T>
  void field(const char* name, T& value, const SettingNote&) {
    if constexpr (std::is_same_v<T, bool>) {
      value = !value;
    } else if constexpr (std::is_enum_v<T>) {
      for (const auto& entry : enum_names(value))
        if (entry.value != value) {
          value = entry.value;
          break;
        }
    } else {
      static_assert(std::is_unsigned_v<T>);
      ++value;
    }
    note(name, setting_value_text(value));
  }

  template <class T>
  void field(const char* name, T& value, const Range& range, const SettingNote&) {
    const std::optional<T> other = other_value(value, range);
    if (!other) {
      ADD_FAILURE() << dotted(name) << ": no other value in " << range_text(range);
      return;
    }
    value = *other;
    note(name, setting_value_text(value));
  }

  template <class S>
  void section(const char* name, S& settings, const char*) {
    sections_.push_back(name);
    visit_fields(settings, *this);
    sections_.pop_back();
  }

  const std::vector<Probe>& probes() const { return probes_; }

 private:
  void note(const char* name, const std::string& text) {
    std::string document, indent;
    for (const std::string& section : sections_) {
      document += indent + section + ":\n";
      indent += "  ";
    }
    const std::string line = indent + name + ": " + text;
    probes_.push_back({dotted(name), document + line + "\n", line});
  }
  std::string dotted(const char* name) const {
    std::string key;
    for (const std::string& section : sections_) key += section + ".";
    return key + name;
  }

  std::vector<std::string> sections_;
  std::vector<Probe> probes_;
};

TEST(SettingsFields, EveryKeySetFromYamlChangesThatFieldAlone) {
  Settings changed;
  ValueChanger changer;
  visit_fields(changed, changer);
  ASSERT_GT(changer.probes().size(), 140u);  // the walk reached every section

  const std::vector<std::string> defaults = lines_of(settings_yaml_text(Settings{}));
  for (const Probe& probe : changer.probes()) {
    Settings read;
    try {
      read_settings_node(YAML::Load(probe.document), "probe.yaml", read);
    } catch (const std::exception& e) {
      ADD_FAILURE() << probe.key << ": " << e.what();
      continue;
    }
    const std::vector<std::string> written = lines_of(settings_yaml_text(read));
    ASSERT_EQ(written.size(), defaults.size()) << probe.key;
    std::vector<std::string> differing;
    for (size_t i = 0; i < written.size(); ++i)
      if (written[i] != defaults[i]) differing.push_back(written[i]);
    EXPECT_EQ(differing, std::vector<std::string>{probe.written_line})
        << "setting " << probe.key << " from YAML:\n"
        << probe.document;
  }
}

// `slamkit settings` prints this text (tests/cli/settings_command_e2e_test.cpp).
TEST(SettingsYamlText, ReadOverOtherSettingsGivesBackEveryDefault) {
  Settings changed;
  ValueChanger changer;
  visit_fields(changed, changer);
  read_settings_node(YAML::Load(settings_yaml_text(Settings{})), "settings output", changed);
  EXPECT_EQ(settings_yaml_text(changed), settings_yaml_text(Settings{}));
}

TEST(AggregateArity, CountsMembersOfEveryKind) {
  struct Sample {
    int count = 1;
    double scale = 2;
    bool on = false;
    FastType type = FastType::kFast9;
    OrbSettings nested;
  };
  static_assert(aggregate_arity<Sample>() == 5);
  static_assert(aggregate_arity<Settings>() == 11);
}

// Counts the field and section calls of one struct's visit_fields, and checks each nested
// struct in turn.
class VisitCounter {
 public:
  VisitCounter(std::string name, int& structs) : name_(std::move(name)), structs_(structs) {}

  template <class T>
  void field(const char*, T&, const SettingNote&) {
    ++calls_;
  }
  template <class T>
  void field(const char*, T&, const Range&, const SettingNote&) {
    ++calls_;
  }
  template <class S>
  void section(const char* name, S& settings, const char*) {
    ++calls_;
    expect_every_member_visited(settings, name_ + "." + name, structs_);
  }

  template <class S>
  static void expect_every_member_visited(S& settings, const std::string& name, int& structs) {
    VisitCounter counter(name, structs);
    visit_fields(settings, counter);
    ++structs;
    EXPECT_EQ(counter.calls_, aggregate_arity<S>())
        << name << ": a member of the struct has no field() or section() line in "
        << "lib/io/settings_fields.h, so no settings file can set it";
  }

 private:
  std::string name_;
  int& structs_;
  size_t calls_ = 0;
};

TEST(SettingsFields, EveryStructMemberIsVisited) {
  Settings settings;
  int structs = 0;
  VisitCounter::expect_every_member_visited(settings, "Settings", structs);
  EXPECT_EQ(structs, 19);  // Settings, its 11 sections, 4 in tracking and 3 in optimization
}

}  // namespace
}  // namespace slamkit
