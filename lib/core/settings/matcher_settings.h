#pragma once
// Descriptor matching settings (SPEC section 2). "(paper)" marks the source's values; the others
// say where they come from.

namespace slamkit {

enum class MatcherBackend {
  kFlannLsh,    // (paper) approximate nearest neighbours, FLANN with an LSH index
  kBruteForce,  // exact: cv::BFMatcher with NORM_HAMMING
};

struct MatcherSettings {
  // Frame-to-frame matching of two descriptor sets.
  MatcherBackend backend = MatcherBackend::kFlannLsh;  // (paper)
  int lsh_table_number = 12;      // LSH hash tables (OpenCV's documented example values)
  int lsh_key_size = 20;          // bits per hash key
  int lsh_multi_probe_level = 2;  // neighbouring buckets probed
  unsigned lsh_seed = 0x5eed;     // seeds the bit choice of the LSH tables: results repeat
  double ratio = 0.8;             // (beyond) Lowe's ratio best/second best; 1 = off
  bool mutual_check = true;       // (beyond) keep a match only if it is best both ways
  int max_distance = 50;          // Hamming bits; ORB-SLAM2's TH_LOW

  // Guided matching of map points projected into a frame (ORB-SLAM2's SearchByProjection).
  double projection_radius = 15;      // search radius in level-0 pixels, times the level scale;
                                      // ORB-SLAM2's motion-model window for RGB-D (th = 15)
  int projection_max_distance = 100;  // Hamming bits; ORB-SLAM2's TH_HIGH
  double projection_ratio = 0.8;      // best/second best (ORB-SLAM2's local-map nnratio 0.8)
  int projection_octave_window = 1;   // keypoint level within +-this of the point's level
  double grid_cell_size = 10;         // keypoint grid cell in pixels (ORB-SLAM2: 640/64 = 10)
};

}  // namespace slamkit
