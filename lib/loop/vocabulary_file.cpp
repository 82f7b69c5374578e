// The binary vocabulary format of vocabulary_file.h.
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>

#include "core/error.h"
#include "core/fingerprint.h"
#include "io/atomic_file.h"
#include "loop/vocabulary_file.h"

namespace slamkit {
namespace {

constexpr char kMagic[8] = {'S', 'K', 'V', 'O', 'C', 'A', 'B', '\0'};

void put_u32(std::string& out, uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
}
void put_u64(std::string& out, uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(char((v >> (8 * i)) & 0xff));
}

uint64_t checksum(const char* data, size_t size) {
  Fnv1a64 hash;
  hash.add(data, size);
  return hash.value();
}

// Reads little-endian values from the file's bytes; running past the end is a damaged file.
class Reader {
 public:
  Reader(const std::string& bytes, size_t end, const std::string& path)
      : bytes_(bytes), end_(end), path_(path) {}
  uint64_t take(int size) {
    need(size);
    uint64_t v = 0;
    for (int i = 0; i < size; ++i) v |= uint64_t(uint8_t(bytes_[pos_ + i])) << (8 * i);
    pos_ += size;
    return v;
  }
  void copy(uint8_t* out, size_t size) {
    need(size);
    std::memcpy(out, bytes_.data() + pos_, size);
    pos_ += size;
  }
  bool at_end() const { return pos_ == end_; }

 private:
  void need(size_t size) {
    if (end_ - pos_ < size) throw_input_error(path_, "truncated vocabulary file");
  }
  const std::string& bytes_;
  size_t end_;
  size_t pos_ = 0;
  const std::string& path_;
};

Vocabulary read_binary_vocabulary(const std::string& bytes, const std::string& path) {
  if (bytes.size() < sizeof kMagic + 8) throw_input_error(path, "truncated vocabulary file");
  Reader reader(bytes, bytes.size() - 8, path);
  reader.take(sizeof kMagic);
  const uint32_t version = uint32_t(reader.take(4));
  if (version != kVocabularyFileVersion)
    throw_input_error(path, "vocabulary file version " + std::to_string(version) +
                                ", this slamkit reads version " +
                                std::to_string(kVocabularyFileVersion));
  uint64_t stored = 0;
  for (int i = 0; i < 8; ++i) stored |= uint64_t(uint8_t(bytes[bytes.size() - 8 + i])) << (8 * i);
  if (stored != checksum(bytes.data(), bytes.size() - 8))
    throw_input_error(path, "vocabulary file checksum mismatch: the file is damaged");

  const int branching = int(reader.take(4));
  const int depth = int(reader.take(4));
  const uint32_t count = uint32_t(reader.take(4));
  if (count == 0) throw_input_error(path, "vocabulary file without a root node");
  if (uint64_t(count - 1) * (4 + kDescriptorBytes) > bytes.size())
    throw_input_error(path, "truncated vocabulary file");
  std::vector<VocabularyNode> nodes(1);
  nodes.reserve(count);
  for (uint32_t i = 1; i < count; ++i) {
    VocabularyNode node;
    node.parent = uint32_t(reader.take(4));
    reader.copy(node.descriptor.data(), kDescriptorBytes);
    if (node.parent >= i) throw_input_error(path, "node " + std::to_string(i) + " before its parent");
    nodes.push_back(node);
  }
  Vocabulary vocabulary(branching, depth, std::move(nodes));
  std::vector<double> weights(vocabulary.word_count());
  for (double& w : weights) {
    const uint64_t bits = reader.take(8);
    std::memcpy(&w, &bits, sizeof w);
  }
  if (!reader.at_end()) throw_input_error(path, "vocabulary file has trailing bytes");
  vocabulary.set_weights(weights);
  return vocabulary;
}

}  // namespace

void save_vocabulary(const std::filesystem::path& path, const Vocabulary& vocabulary) {
  const auto& nodes = vocabulary.nodes();
  std::string out(kMagic, sizeof kMagic);
  put_u32(out, kVocabularyFileVersion);
  put_u32(out, uint32_t(vocabulary.branching()));
  put_u32(out, uint32_t(vocabulary.depth()));
  put_u32(out, uint32_t(nodes.size()));
  for (size_t i = 1; i < nodes.size(); ++i) {
    put_u32(out, nodes[i].parent);
    out.append(reinterpret_cast<const char*>(nodes[i].descriptor.data()), kDescriptorBytes);
  }
  for (WordId w = 0; w < vocabulary.word_count(); ++w) {
    uint64_t bits;
    const double weight = vocabulary.weight(w);
    std::memcpy(&bits, &weight, sizeof bits);
    put_u64(out, bits);
  }
  put_u64(out, checksum(out.data(), out.size()));
  write_file_atomically(path, [&](std::ostream& s) { s.write(out.data(), out.size()); });
}

Vocabulary load_vocabulary(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw_input_error(path.string(), "cannot open vocabulary file");
  char magic[sizeof kMagic] = {};
  in.read(magic, sizeof magic);
  if (in.gcount() != sizeof magic || std::memcmp(magic, kMagic, sizeof kMagic) != 0)
    return read_orbvoc_text(path);
  in.seekg(0);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return read_binary_vocabulary(bytes.str(), path.string());
}

}  // namespace slamkit
