#pragma once
// ORB extraction settings (docs/method.md#features). Each default is tagged with its source:
// (paper), (ORB-SLAM2) or (slamkit) (docs/method.md#sources).

namespace slamkit {

// Segment test of the FAST detector on the 16-pixel circle of radius 3.
enum class FastType {
  kFast12,  // (paper) 12 contiguous pixels, quick test on pixels 1, 5, 9, 13
  kFast9,   // 9 contiguous pixels: OpenCV's TYPE_9_16, what ORB-SLAM2 and cv::ORB use
};

struct OrbSettings {
  int num_features = 1000;    // (ORB-SLAM2) M, corners kept per frame over all levels
  int pyramid_levels = 4;     // (paper)
  double scale_factor = 1.2;  // (paper) level l is the image scaled by 1/scale_factor^l
  // (slamkit) FAST-9, not the paper's FAST-12: OpenCV has no FAST-12 on 16 pixels (ours
  // filters FAST-9 candidates), and on fr1/desk and fr2/desk FAST-12 is less repeatable
  // (tests/features/cv_orb_comparison_test.cpp). kFast12 gives the paper's.
  FastType fast_type = FastType::kFast9;
  int fast_threshold = 20;  // (ORB-SLAM2) FAST intensity threshold, its iniThFAST
  // (ORB-SLAM2) Retried in grid cells where the first finds nothing (its minThFAST); only with
  // spread_over_image. Such corners only fill what the stronger ones leave of the quota.
  int fast_min_threshold = 7;
  bool spread_over_image = true;  // (slamkit) grid per level; false = best M by response (paper)
  // (ORB-SLAM2) Grid cell in level pixels, for the retry and the spreading (its detection
  // cell W = 30).
  int cell_size = 30;
  // (slamkit) With spreading, no cell keeps more than this times its fair share (level quota /
  // cells holding corners); lower spreads more but costs repeatability.
  double max_cell_share = 5.0;
  int shi_tomasi_block_size = 7;  // (slamkit) structure tensor window (cv::ORB's Harris block)
  // (ORB-SLAM2) Level pixels from the border where no corner is kept: the rotated BRIEF
  // pattern reaches 19 px.
  int edge_threshold = 19;
};

}  // namespace slamkit
