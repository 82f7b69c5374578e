#include "io/yaml_file.h"

#include "core/error.h"
#include "io/atomic_file.h"
#include "io/path_kind.h"

namespace slamkit {

YAML::Node load_yaml_file(const std::filesystem::path& path, const std::string& what) {
  const std::string name = path.string();
  const PathKind kind = path_kind(path);
  if (kind == PathKind::kMissing) throw_input_error(name, what + " not found");
  if (kind == PathKind::kFolder) throw_input_error(name, "is a folder, expected a file");
  std::error_code error;
  const uintmax_t size = std::filesystem::file_size(path, error);
  if (!error && size > kMaxYamlBytes)
    throw_input_error(name, what + " of " + std::to_string(size >> 20) + " MiB: larger than the " +
                                std::to_string(kMaxYamlBytes >> 20) + " MiB a YAML file may have");
  try {
    return YAML::LoadFile(name);
  } catch (const YAML::Exception& e) {
    throw_input_error(name, e.mark.line + 1, "YAML error: " + e.msg);
  }
}

std::string scalar_text(const YAML::Node& node, const std::string& path, const std::string& what) {
  if (node.IsScalar()) return node.Scalar();
  const char* kind = node.IsMap() ? "a map" : node.IsSequence() ? "a list" : "empty";
  const std::string message = what + " must be a plain value, found " + kind;
  if (node.Mark().is_null()) throw_input_error(path, message);
  throw_input_error(path, node.Mark().line + 1, message);
}

void write_yaml_file(const std::filesystem::path& path, const YAML::Emitter& document) {
  if (path.has_parent_path()) std::filesystem::create_directories(path.parent_path());
  write_file_atomically(path, [&](std::ostream& out) { out << document.c_str() << "\n"; });
}

}  // namespace slamkit
