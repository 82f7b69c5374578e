#pragma once
// Descriptor matching settings (docs/method.md#matching-and-pose). Each default is tagged with
// its source: (paper), (ORB-SLAM2) or (slamkit) (docs/method.md#sources).

namespace slamkit {

enum class MatcherBackend {
  kFlannLsh,    // (paper) approximate nearest neighbours, FLANN with an LSH index
  kBruteForce,  // exact: cv::BFMatcher with NORM_HAMMING
};

struct MatcherSettings {
  // Frame-to-frame matching of two descriptor sets.
  MatcherBackend backend = MatcherBackend::kFlannLsh;  // (paper)
  int lsh_table_number = 12;      // (slamkit) LSH hash tables (OpenCV's documented example values)
  int lsh_key_size = 20;          // (slamkit) bits per hash key
  int lsh_multi_probe_level = 2;  // (slamkit) neighbouring buckets probed
  unsigned lsh_seed = 0x5eed;  // (slamkit) seeds the bit choice of the LSH tables: results repeat
  double ratio = 0.8;          // (slamkit) Lowe's ratio best/second best; 1 = off
  bool mutual_check = true;    // (slamkit) keep a match only if it is best both ways
  int max_distance = 50;       // (ORB-SLAM2) Hamming bits; its TH_LOW

  // Guided matching of map points projected into a frame (ORB-SLAM2's SearchByProjection).
  // (ORB-SLAM2) Search radius in level-0 pixels, times the level scale: its motion-model window
  // for RGB-D (th = 15).
  double projection_radius = 15;
  int projection_max_distance = 100;  // (ORB-SLAM2) Hamming bits; its TH_HIGH
  double projection_ratio = 0.8;      // (ORB-SLAM2) best/second best, its local-map nnratio
  int projection_octave_window = 1;   // (slamkit) keypoint level within +-this of the point's level
  double grid_cell_size = 10;         // (ORB-SLAM2) keypoint grid cell in pixels (640/64 = 10)
};

}  // namespace slamkit
