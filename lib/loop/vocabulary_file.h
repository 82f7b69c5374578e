#pragma once
// Vocabulary files: our own compact binary format, and ORB-SLAM2's ORBvoc.txt (DBoW2's text
// format) so a user can bring the standard vocabulary.
//
// The binary format, all integers little-endian:
//   magic "SKVOCAB\0" (8 bytes), u32 version (1), u32 branching, u32 depth, u32 node count,
//   per node except the root: u32 parent, 32 descriptor bytes;
//   per word (node order): f64 weight (IEEE 754 bits);
//   u64 FNV-1a of every byte before it.
#include <filesystem>

#include "loop/vocabulary.h"

namespace slamkit {

inline constexpr uint32_t kVocabularyFileVersion = 1;

// Writes the binary format (atomically: see io/atomic_file.h).
void save_vocabulary(const std::filesystem::path& path, const Vocabulary& vocabulary);

// Reads either format, told apart by the magic. Throws InputError naming the file (and the
// line, in a text file) when it is missing, of another version, damaged (checksum) or
// malformed.
Vocabulary load_vocabulary(const std::filesystem::path& path);

// DBoW2's text format: a first line "k L scoring weighting", then one line per node after the
// root, "parent_id is_leaf d_0 ... d_31 weight", node ids counting from 1 in line order.
// Only L1-norm scoring with TF-IDF weighting (0 0, as ORBvoc.txt) is accepted.
Vocabulary read_orbvoc_text(const std::filesystem::path& path);

}  // namespace slamkit
