#include "loop/vocabulary_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "loop/loop_test_support.h"
#include "loop/vocabulary_training.h"
#include "support/test_data.h"

namespace slamkit {
namespace {

namespace fs = std::filesystem;

Vocabulary trained() {
  VocabularySettings s;
  s.branching = 6;
  s.depth = 3;
  return train_vocabulary(test::clustered_images(10, 300, 500, 4), s);
}

std::string error_of(const fs::path& path) {
  try {
    load_vocabulary(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

void xor_byte(const fs::path& path, long offset, char mask) {
  std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
  f.seekg(offset);
  const char old = char(f.get());
  f.seekp(offset);
  f.put(char(old ^ mask));
}

TEST(VocabularyFile, SaveLoadRoundTripGivesTheSameWords) {
  const Vocabulary original = trained();
  const fs::path path = test::temp_dir("vocabulary_file") / "vocab.bin";
  save_vocabulary(path, original);
  const Vocabulary loaded = load_vocabulary(path);
  EXPECT_EQ(loaded.branching(), 6);
  EXPECT_EQ(loaded.depth(), 3);
  ASSERT_EQ(loaded.word_count(), original.word_count());
  for (WordId w = 0; w < original.word_count(); ++w)
    EXPECT_EQ(loaded.weight(w), original.weight(w));
  std::mt19937 rng(1);
  const cv::Mat descriptors = test::random_descriptors(2000, rng);
  for (int r = 0; r < descriptors.rows; ++r)
    EXPECT_EQ(loaded.transform(descriptors.ptr<uint8_t>(r)),
              original.transform(descriptors.ptr<uint8_t>(r)));
}

TEST(VocabularyFile, WrongVersionIsRefusedNamingTheFile) {
  const fs::path path = test::temp_dir("vocabulary_version") / "vocab.bin";
  save_vocabulary(path, trained());
  xor_byte(path, 8, 6);  // version 1 becomes 7: the version follows the 8-byte magic
  EXPECT_EQ(error_of(path),
            path.string() + ": vocabulary file version 7, this slamkit reads version 1");
}

TEST(VocabularyFile, DamagedFileFailsItsChecksum) {
  const fs::path path = test::temp_dir("vocabulary_checksum") / "vocab.bin";
  save_vocabulary(path, trained());
  xor_byte(path, 100, 0x10);
  EXPECT_EQ(error_of(path),
            path.string() + ": vocabulary file checksum mismatch: the file is damaged");
}

// A k = 2, L = 2 tree in DBoW2's text format: inner nodes 1 (zeros) and 2 (ones), leaves 3, 4
// under 1 and 5, 6 under 2.
std::string descriptor_text(int first_byte, int other_bytes) {
  std::string text = std::to_string(first_byte);
  for (int i = 1; i < 32; ++i) text += " " + std::to_string(other_bytes);
  return text;
}

fs::path write_orbvoc(const std::string& tag, const std::string& node_lines) {
  const fs::path path = test::temp_dir(tag) / "ORBvoc.txt";
  std::ofstream(path) << "2 2  0 0\n" << node_lines;
  return path;
}

const std::string kNodes = "0 0 " + descriptor_text(0, 0) + " 0\n" +       // node 1
                           "0 0 " + descriptor_text(255, 255) + " 0\n" +   // node 2
                           "1 1 " + descriptor_text(0, 0) + " 0.1\n" +     // node 3, word 0
                           "1 1 " + descriptor_text(15, 0) + " 0.2\n" +    // node 4, word 1
                           "2 1 " + descriptor_text(255, 255) + " 0.3\n" + // node 5, word 2
                           "2 1 " + descriptor_text(240, 255) + " 0.4\n";  // node 6, word 3

TEST(OrbVocText, LoadsDbow2TextFormat) {
  const Vocabulary v = load_vocabulary(write_orbvoc("orbvoc", kNodes));
  EXPECT_EQ(v.branching(), 2);
  EXPECT_EQ(v.depth(), 2);
  ASSERT_EQ(v.word_count(), 4u);
  EXPECT_DOUBLE_EQ(v.weight(3), 0.4);
  uint8_t d[32] = {0x07};  // 3 bits from node 1, 1 bit from node 4, 3 from node 3
  EXPECT_EQ(v.transform(d), 1u);
  NodeId node;
  v.transform(d, 1, &node);
  EXPECT_EQ(node, 1u);
  for (uint8_t& byte : d) byte = 0xff;
  d[0] = 0xf1;  // 3 bits from node 5, 1 from node 6
  EXPECT_EQ(v.transform(d), 3u);
}

TEST(OrbVocText, MalformedLineNamesFileAndLine) {
  const std::string short_descriptor = "1 1 " + descriptor_text(0, 0).substr(2) + "\n";
  const fs::path path = write_orbvoc("orbvoc_bad", kNodes.substr(0, kNodes.find("1 1 ")) +
                                                       short_descriptor);
  EXPECT_EQ(error_of(path).rfind(path.string() + ":4: ", 0), 0u) << error_of(path);

  const fs::path orphan = write_orbvoc("orbvoc_parent", "7 1 " + descriptor_text(0, 0) + " 1\n");
  EXPECT_EQ(error_of(orphan), orphan.string() + ":2: expected parent id (0..0)");

  const fs::path scoring = test::temp_dir("orbvoc_scoring") / "voc.txt";
  std::ofstream(scoring) << "10 6 1 0\n";
  EXPECT_EQ(error_of(scoring),
            scoring.string() + ":1: only L1-norm scoring with TF-IDF weighting (0 0) is supported");
  EXPECT_EQ(error_of("/nonexistent/voc.bin"), "/nonexistent/voc.bin: cannot open vocabulary file");
}

}  // namespace
}  // namespace slamkit
