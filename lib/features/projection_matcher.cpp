#include "features/projection_matcher.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "features/descriptor.h"

namespace slamkit {
namespace {

// The level scale for a point seen at `octave`; 1 when unknown.
double octave_scale(const FrameFeatures& frame, const MapPointSet& points, size_t i) {
  if (points.octaves.empty()) return 1.0;
  const int octave = points.octaves[i];
  if (octave < frame.pyramid.size()) return frame.pyramid.scales[octave];
  // A point from a deeper pyramid than this frame's: extend the geometric series.
  const double factor = frame.pyramid.size() > 1 ? frame.pyramid.scales[1] : 1.0;
  return std::pow(factor, octave);
}

}  // namespace

std::vector<ProjectionMatch> match_by_projection(const MapPointSet& points,
                                                 const Eigen::Isometry3d& T_w_c,
                                                 const Camera& camera, const FrameFeatures& frame,
                                                 const KeypointGrid& grid,
                                                 const MatcherSettings& settings) {
  const Eigen::Isometry3d T_c_w = T_w_c.inverse();
  // For each keypoint, the best claim so far (point index and distance).
  std::vector<ProjectionMatch> claim(frame.size());
  std::vector<int> candidates;

  for (size_t i = 0; i < points.points_w.size(); ++i) {
    const Eigen::Vector3d p_c = T_c_w * points.points_w[i];
    if (p_c.z() <= 0) continue;
    const Eigen::Vector2d uv = camera.project(p_c);
    const double radius = settings.projection_radius * octave_scale(frame, points, i);
    const uchar* descriptor = points.descriptors.ptr<uchar>(static_cast<int>(i));

    int best = std::numeric_limits<int>::max(), second = best, best_keypoint = -1;
    grid.within(uv, radius, candidates);
    for (int k : candidates) {
      if (!points.octaves.empty() && std::abs(frame.keypoints[k].octave - points.octaves[i]) >
                                         settings.projection_octave_window) {
        continue;
      }
      const int d = descriptor_distance(descriptor, frame.descriptors.ptr<uchar>(k));
      if (d < best) {
        second = best, best = d, best_keypoint = k;
      } else if (d < second) {
        second = d;
      }
    }
    if (best_keypoint < 0 || best > settings.projection_max_distance) continue;
    if (second != std::numeric_limits<int>::max() && best >= settings.projection_ratio * second) {
      continue;
    }
    ProjectionMatch& c = claim[best_keypoint];
    if (c.point < 0 || best < c.distance) c = {static_cast<int>(i), best_keypoint, best};
  }

  std::vector<ProjectionMatch> matches;
  for (const ProjectionMatch& c : claim) {
    if (c.point >= 0) matches.push_back(c);
  }
  std::sort(matches.begin(), matches.end(),
            [](const ProjectionMatch& a, const ProjectionMatch& b) { return a.point < b.point; });
  return matches;
}

}  // namespace slamkit
