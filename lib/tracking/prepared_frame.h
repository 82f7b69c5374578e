#pragma once
// What the parallel stage computes for a frame, so that tracking only tracks.
#include <opencv2/core.hpp>
#include <vector>

#include "features/frame_features.h"
#include "keyframes/window_code.h"

namespace slamkit {

struct PreparedFrame {
  size_t index = 0;
  double stamp = 0;        // the colour image's
  double depth_stamp = 0;  // the depth image's (TumSequence::depth_stamp)
  cv::Mat depth;           // CV_32F metres as recorded (registered to colour, raw lens geometry)
  cv::Mat rgb;             // CV_8UC3 BGR, for the map's fusion should the frame become a keyframe
  // The tracker moves features.undistorted and keypoint_depths to the colour stamp
  // (tracking/exposure_unrolling.h) once it knows the camera's velocity.
  FrameFeatures features;
  std::vector<float> keypoint_depths;  // metres per keypoint, 0 = none
  WindowCode window_code;
  // Per-stage wall time of this frame, milliseconds.
  double decode_ms = 0, features_ms = 0, window_code_ms = 0;
};

}  // namespace slamkit
