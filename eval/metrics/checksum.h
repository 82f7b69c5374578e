#pragma once
// A file fingerprint for metrics.json, so a result can be traced to the exact input.
#include <filesystem>
#include <string>

namespace slamkit::eval {

// FNV-1a 64-bit of the file's bytes as 16 hex digits (core/fingerprint.h). Throws InputError
// when the file cannot be read.
std::string fnv1a64_file(const std::filesystem::path& path);

}  // namespace slamkit::eval
