#include "loop/vocabulary_training.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <array>
#include <cmath>

#include "features/descriptor.h"
#include "loop/k_medians.h"
#include "loop/loop_test_support.h"

namespace slamkit {
namespace {

VocabularySettings small_tree(int k, int depth) {
  VocabularySettings s;
  s.branching = k;
  s.depth = depth;
  return s;
}

void expect_same_tree(const Vocabulary& a, const Vocabulary& b) {
  ASSERT_EQ(a.nodes().size(), b.nodes().size());
  for (size_t i = 0; i < a.nodes().size(); ++i) {
    EXPECT_EQ(a.nodes()[i].parent, b.nodes()[i].parent) << "node " << i;
    EXPECT_EQ(a.nodes()[i].descriptor, b.nodes()[i].descriptor) << "node " << i;
    EXPECT_EQ(a.nodes()[i].weight, b.nodes()[i].weight) << "node " << i;
  }
}

TEST(VocabularyTraining, SameInputGivesTheSameTreeAtAnyThreadCount) {
  // 24,000 descriptors: enough for k-medians to share its root-level work among threads.
  const auto images = test::clustered_images(40, 600, 3000, 7);
  const VocabularySettings settings = small_tree(8, 4);
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Vocabulary one = train_vocabulary(images, settings);
  omp_set_num_threads(2);
  const Vocabulary two = train_vocabulary(images, settings);
  omp_set_num_threads(threads);
  EXPECT_GT(one.word_count(), 1000u);
  expect_same_tree(one, two);
  expect_same_tree(one, train_vocabulary(images, settings));

  VocabularySettings reseeded = settings;
  reseeded.seed += 1;
  EXPECT_NE(train_vocabulary(images, reseeded).nodes()[1].descriptor, one.nodes()[1].descriptor);
}

TEST(VocabularyTraining, DescriptorLandsInTheWordOfItsNearestCentreAtEveryLevel) {
  const auto images = test::clustered_images(20, 300, 800, 3);
  const VocabularySettings settings = small_tree(5, 4);
  const Vocabulary vocabulary = train_vocabulary(images, settings);
  const auto& nodes = vocabulary.nodes();
  std::mt19937 rng(11);
  const cv::Mat queries = test::flip_bits(images[0], 20, rng);  // off the training data
  for (int q = 0; q < queries.rows; ++q) {
    const uint8_t* d = queries.ptr<uint8_t>(q);
    NodeId parent = 0;
    for (int level = 1; level <= settings.depth; ++level) {
      NodeId node;
      const WordId word = vocabulary.transform(d, level, &node);
      if (node == parent) break;  // reached a leaf above this level
      ASSERT_EQ(nodes[node].parent, parent) << "the path goes down one level at a time";
      const int chosen = descriptor_distance(d, nodes[node].descriptor.data());
      for (size_t sibling = 1; sibling < nodes.size(); ++sibling) {
        if (nodes[sibling].parent == parent) {
          EXPECT_LE(chosen, descriptor_distance(d, nodes[sibling].descriptor.data()))
              << "descriptor " << q << " level " << level;
        }
      }
      EXPECT_EQ(word, vocabulary.transform(d));
      parent = node;
    }
  }
}

TEST(VocabularyTraining, WordWeightIsLogImagesOverImagesWithTheWord) {
  std::mt19937 rng(5);
  const cv::Mat p = test::random_descriptors(3, rng);
  // P0 in all four images, P2 in two, P1 in one.
  std::vector<cv::Mat> images(4);
  for (int i = 0; i < 4; ++i) images[i].push_back(p.row(0));
  images[0].push_back(p.row(1));
  images[0].push_back(p.row(2));
  images[1].push_back(p.row(2));
  const Vocabulary vocabulary = train_vocabulary(images, small_tree(3, 1));
  ASSERT_EQ(vocabulary.word_count(), 3u);
  EXPECT_DOUBLE_EQ(vocabulary.weight(vocabulary.transform(p.ptr<uint8_t>(0))), 0.0);
  EXPECT_DOUBLE_EQ(vocabulary.weight(vocabulary.transform(p.ptr<uint8_t>(1))), std::log(4.0));
  EXPECT_DOUBLE_EQ(vocabulary.weight(vocabulary.transform(p.ptr<uint8_t>(2))), std::log(2.0));
}

TEST(KMedians, CentreIsTheBitwiseMajority) {
  const uint8_t a[32] = {0b0111}, b[32] = {0b0011}, c[32] = {0b1001};
  const Descriptor centre = majority_descriptor({a, b, c});
  EXPECT_EQ(centre[0], 0b0011);
  EXPECT_EQ(majority_descriptor({a, c})[0], 0b0001) << "a tie gives 0: the AND of two";
}

TEST(KMedians, MajorityOfManyMembersEqualsCountingEachBit) {
  // More than 255 members: the counts carry over between the lane-wise partial sums.
  std::mt19937 rng(4);
  const cv::Mat d = test::random_descriptors(1001, rng);
  std::vector<const uint8_t*> rows;
  std::array<int, 256> ones{};
  for (int r = 0; r < d.rows; ++r) {
    rows.push_back(d.ptr<uint8_t>(r));
    for (int bit = 0; bit < 256; ++bit) ones[size_t(bit)] += (d.at<uint8_t>(r, bit / 8) >> (bit % 8)) & 1;
  }
  const Descriptor centre = majority_descriptor(rows);
  for (int bit = 0; bit < 256; ++bit)
    EXPECT_EQ((centre[size_t(bit / 8)] >> (bit % 8)) & 1, 2 * ones[size_t(bit)] > d.rows ? 1 : 0)
        << "bit " << bit << ": " << ones[size_t(bit)] << " of " << d.rows << " set";
}

TEST(KMedians, SeparatedGroupsBecomeTheClusters) {
  std::mt19937 rng(9);
  const cv::Mat centres = test::random_descriptors(4, rng);
  cv::Mat members;
  for (int g = 0; g < 4; ++g)
    for (int i = 0; i < 50; ++i) members.push_back(centres.row(g));
  members = test::flip_bits(members, 10, rng);
  std::vector<const uint8_t*> rows;
  for (int r = 0; r < members.rows; ++r) rows.push_back(members.ptr<uint8_t>(r));
  const Clustering c = k_medians(rows, 4, 10, 1);
  ASSERT_EQ(c.centres.size(), 4u);
  for (int g = 0; g < 4; ++g)
    for (int i = 0; i < 50; ++i) EXPECT_EQ(c.assignment[g * 50 + i], c.assignment[g * 50]);
  for (int g = 0; g < 4; ++g)  // the majority of 50 noisy copies is the original
    EXPECT_LE(descriptor_distance(c.centres[c.assignment[g * 50]].data(), centres.ptr<uint8_t>(g)),
              2);
}

TEST(KMedians, FewerDistinctMembersThanKGiveOneClusterEach) {
  std::mt19937 rng(2);
  const cv::Mat d = test::random_descriptors(2, rng);
  const std::vector<const uint8_t*> rows = {d.ptr<uint8_t>(0), d.ptr<uint8_t>(1), d.ptr<uint8_t>(0)};
  const Clustering c = k_medians(rows, 10, 10, 1);
  ASSERT_EQ(c.centres.size(), 2u);
  EXPECT_EQ(c.assignment[0], c.assignment[2]);
  EXPECT_NE(c.assignment[0], c.assignment[1]);
}

}  // namespace
}  // namespace slamkit
