#include "eval/metrics/checksum.h"

#include <fstream>
#include <vector>

#include "core/error.h"
#include "core/fingerprint.h"

namespace slamkit::eval {

std::string fnv1a64_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error(path.string(), "cannot read file");
  Fnv1a64 hash;
  std::vector<char> buffer(1 << 16);
  while (in.read(buffer.data(), std::streamsize(buffer.size())) || in.gcount() > 0)
    hash.add(buffer.data(), size_t(in.gcount()));
  return hash.hex();
}

}  // namespace slamkit::eval
