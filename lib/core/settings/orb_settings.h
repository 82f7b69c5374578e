#pragma once
// ORB extraction settings (SPEC section 1). "(paper)" values are the source's defaults.

namespace slamkit {

struct OrbSettings {
  int num_features = 1000;    // M, corners kept per frame over all levels
  int pyramid_levels = 4;     // (paper)
  double scale_factor = 1.2;  // (paper) level l is the image scaled by 1/scale_factor^l
  int fast_threshold = 20;    // FAST intensity threshold (ORB-SLAM2's iniThFAST)
  int fast_min_threshold = 7; // retried in grid cells where the first finds nothing
  bool spread_over_image = true;  // (beyond) grid per level; false = global best M (paper)
};

}  // namespace slamkit
