#include "bin/output_folder.h"

#include <optional>
#include <system_error>

#include "core/error.h"

namespace slamkit::cli {
namespace {

namespace fs = std::filesystem;

bool is_file_not_folder(const fs::path& path) {
  std::error_code error;
  return fs::exists(path, error) && !fs::is_directory(path, error);
}

// The nearest parent of `path` that exists and is not a folder, if any.
std::optional<fs::path> parent_that_is_a_file(const fs::path& path) {
  for (fs::path p = path.parent_path(); !p.empty() && p != p.parent_path(); p = p.parent_path())
    if (is_file_not_folder(p)) return p;
  return std::nullopt;
}

[[noreturn]] void refuse(const std::string& option, const fs::path& path, const std::string& why) {
  throw_input_error(option + " " + path.string(), why);
}

// Absolute, with symlinks and `..` resolved as far as the path exists.
fs::path resolved(const fs::path& path) {
  std::error_code error;
  const fs::path p = fs::weakly_canonical(fs::absolute(path), error);
  return error ? fs::absolute(path).lexically_normal() : p;
}

bool is_inside(const fs::path& path, const fs::path& folder) {
  const fs::path relative = path.lexically_relative(folder);
  return !relative.empty() && *relative.begin() != "..";
}

}  // namespace

void check_output_folder(const std::string& option, const fs::path& folder) {
  if (is_file_not_folder(folder)) refuse(option, folder, "exists and is not a folder");
  if (const auto file = parent_that_is_a_file(folder))
    refuse(option, folder, file->string() + " is a file, not a folder");
}

void check_output_file(const std::string& option, const fs::path& file) {
  std::error_code error;
  if (fs::is_directory(file, error)) refuse(option, file, "is a folder, not a file");
  if (const auto parent = parent_that_is_a_file(file))
    refuse(option, file, parent->string() + " is a file, not a folder");
}

void check_output_outside_sequences(const std::string& option, const fs::path& out,
                                    const std::vector<std::string>& sequences, bool allowed) {
  if (allowed) return;
  const fs::path target = resolved(out);
  for (const std::string& sequence : sequences)
    if (is_inside(target, resolved(sequence)))
      refuse(option, out,
             "is inside the input sequence " + sequence +
                 " (write elsewhere, or give --allow-out-in-sequence)");
}

void add_allow_out_in_sequence_flag(CLI::App* command, bool& allowed) {
  command->add_flag("--allow-out-in-sequence", allowed,
                    "Write --out even inside an input sequence folder (refused otherwise)");
}

}  // namespace slamkit::cli
