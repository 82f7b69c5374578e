#include "settings/settings_yaml.h"

#include <yaml-cpp/yaml.h>

#include <set>
#include <type_traits>

#include "core/error.h"
#include "core/number_format.h"
#include "io/atomic_file.h"
#include "settings/settings_fields.h"
#include "io/yaml_file.h"

namespace slamkit {
namespace {

class YamlWriter {
 public:
  explicit YamlWriter(YAML::Emitter& out) : out_(out) {}

  template <class T>
  void field(const char* name, T& value, const SettingNote&) {
    out_ << YAML::Key << name << YAML::Value;
    if constexpr (std::is_enum_v<T>) {
      out_ << name_of(enum_names(value), value);
    } else if constexpr (std::is_floating_point_v<T>) {
      out_ << format_exact(value);
    } else {
      out_ << value;
    }
  }

  template <class T>
  void field(const char* name, T& value, const Range&, const SettingNote& note) {
    field(name, value, note);
  }

  template <class S>
  void section(const char* name, S& settings, const char*) {
    out_ << YAML::Key << name << YAML::Value << YAML::BeginMap;
    visit_fields(settings, *this);
    out_ << YAML::EndMap;
  }

 private:
  YAML::Emitter& out_;
};

class YamlReader {
 public:
  YamlReader(const YAML::Node& node, std::string prefix, const std::string& path)
      : node_(node), prefix_(std::move(prefix)), path_(path) {}

  template <class T>
  void field(const char* name, T& value, const SettingNote&) {
    // Numbers with limits take a range (settings_fields.h); only these need none.
    static_assert(std::is_same_v<T, bool> || std::is_enum_v<T> || std::is_unsigned_v<T>);
    read(name, value);
  }

  template <class T>
  void field(const char* name, T& value, const Range& range, const SettingNote&) {
    const YAML::Node child = read(name, value);
    if (child && !in_range(double(value), range))
      fail(child, prefix_ + name + ": " + child.Scalar() + " is outside " + range_text(range));
  }

  template <class S>
  void section(const char* name, S& settings, const char*) {
    const YAML::Node child = take(name);
    if (!child) return;
    if (!child.IsMap()) fail(child, prefix_ + name + " must be a map of settings");
    YamlReader nested(child, prefix_ + name + ".", path_);
    visit_fields(settings, nested);
    nested.reject_unknown_keys();
  }

  void reject_unknown_keys() const {
    for (const auto& entry : node_) {
      const std::string key = scalar_text(entry.first, path_, "a setting name");
      if (!known_.count(key)) fail(entry.first, "unknown setting '" + prefix_ + key + "'");
    }
  }

 private:
  // Sets value from the file when the key is there; returns its node (null when absent).
  template <class T>
  YAML::Node read(const char* name, T& value) {
    const YAML::Node child = take(name);
    if (!child) return child;
    if constexpr (std::is_enum_v<T>) {
      const std::string text = scalar_text(child, path_, prefix_ + name);
      const auto named = value_named(enum_names(value), text);
      if (!named)
        fail(child, "'" + text + "' is not a value of " + prefix_ + name + " (" +
                        choices(enum_names(value)) + ")");
      value = *named;
    } else {
      try {
        value = child.as<T>();
      } catch (const YAML::Exception&) {
        fail(child, prefix_ + name + " has the wrong type: '" + child.Scalar() + "'");
      }
    }
    return child;
  }

  YAML::Node take(const char* name) {
    known_.insert(name);
    return node_[name];
  }
  [[noreturn]] void fail(const YAML::Node& at, const std::string& message) const {
    throw_input_error(path_, at.Mark().line + 1, message);
  }

  YAML::Node node_;
  std::string prefix_;
  const std::string& path_;
  std::set<std::string> known_;
};

// Whether a dotted name ("orb.num_features") is a settings field: walks the fields like the
// reader, comparing names instead of reading values.
class FieldFinder {
 public:
  explicit FieldFinder(const std::string& dotted) : dotted_(dotted) {}

  template <class T>
  void field(const char* name, T&, const SettingNote&) {
    found_ = found_ || prefix_ + name == dotted_;
  }
  template <class T>
  void field(const char* name, T& value, const Range&, const SettingNote& note) {
    field(name, value, note);
  }

  template <class S>
  void section(const char* name, S& settings, const char*) {
    const std::string outer = prefix_;
    prefix_ += std::string(name) + ".";
    if (dotted_.rfind(prefix_, 0) == 0) visit_fields(settings, *this);
    prefix_ = outer;
  }

  bool found() const { return found_; }

 private:
  const std::string& dotted_;
  std::string prefix_;
  bool found_ = false;
};

}  // namespace

void read_settings_node(const YAML::Node& root, const std::string& file, Settings& settings) {
  if (root.IsNull()) return;  // nothing set: all defaults
  if (!root.IsMap())
    throw_input_error(file, root.Mark().line + 1, "expected a YAML map of settings sections");
  YamlReader reader(root, "", file);
  visit_fields(settings, reader);
  reader.reject_unknown_keys();
}

void read_settings_yaml(const std::filesystem::path& path, Settings& settings) {
  const std::string name = path.string();
  const YAML::Node root = load_yaml_file(path, "settings file");
  if (!root.IsNull() && !root.IsMap())
    throw_input_error(name, "expected a YAML map of settings sections");
  read_settings_node(root, name, settings);
}

bool is_setting(const std::string& dotted_name) {
  FieldFinder finder(dotted_name);
  Settings defaults;
  visit_fields(defaults, finder);
  return finder.found();
}

void apply_setting(const std::string& dotted_name, const YAML::Node& value, const std::string& file,
                   int line, Settings& settings) {
  if (!is_setting(dotted_name))
    throw_input_error(file, line, "unknown setting '" + dotted_name + "'");
  // The value node keeps its place in the file, so the reader's range and type errors name it.
  YAML::Node root(YAML::NodeType::Map);
  YAML::Node at = root;
  size_t start = 0;
  for (size_t dot; (dot = dotted_name.find('.', start)) != std::string::npos; start = dot + 1) {
    YAML::Node section(YAML::NodeType::Map);
    at[dotted_name.substr(start, dot - start)] = section;
    at.reset(section);
  }
  at[dotted_name.substr(start)] = value;
  read_settings_node(root, file, settings);
}

std::string settings_yaml_text(const Settings& settings) {
  YAML::Emitter out;
  out << YAML::BeginMap;
  YamlWriter writer(out);
  Settings copy = settings;  // the visitor takes fields by reference; the writer only reads
  visit_fields(copy, writer);
  out << YAML::EndMap;
  return std::string(out.c_str()) + "\n";  // as write_yaml_file ends the document
}

void write_settings_yaml(const std::filesystem::path& path, const Settings& settings) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  const std::string text = settings_yaml_text(settings);
  write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace slamkit
