#include "tracking/surface_pyramid.h"

#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

namespace slamkit {
namespace {

// Depth of the plane n.X = d seen by cam (metres, CV_32F).
cv::Mat plane_depth(const Camera& cam, const Eigen::Vector3d& n, double d) {
  cv::Mat depth(cam.height, cam.width, CV_32F);
  for (int v = 0; v < cam.height; ++v)
    for (int u = 0; u < cam.width; ++u)
      depth.at<float>(v, u) = float(d / n.dot(cam.back_project(Eigen::Vector2d(u, v), 1)));
  return depth;
}

Eigen::Vector3d normal_at(const Surface& s, int u, int v) {
  return s.normal(s.index(u, v)).cast<double>();
}

TEST(SurfacePyramid, TiltedPlaneHasItsPointsAndNormalOnEveryLevel) {
  const Camera cam = Camera::freiburg3();
  const Eigen::Vector3d n = Eigen::Vector3d(0.3, -0.2, 1).normalized();
  PointToPlaneSettings raw;
  raw.normal_smoothing_diameter = 0;
  const SurfacePyramid pyramid = make_surface_pyramid(plane_depth(cam, n, 2.0), cam, raw);
  ASSERT_EQ(pyramid.size(), 2u);
  EXPECT_EQ(pyramid[1].width, 320);
  EXPECT_EQ(pyramid[1].camera.fx, cam.fx / 2);
  for (const Surface& s : pyramid) {
    // Central differences: every pixel but the border ones.
    long with_normal = 0;
    double normal_error = 0, plane_distance = 0;
    for (int i = 0; i < int(s.pixels.rows()); ++i) {
      if (!s.has_normal(i)) continue;
      ++with_normal;
      const Eigen::Vector3d p = s.point(i).cast<double>();
      const Eigen::Vector3d normal = s.normal(i).cast<double>();
      normal_error = std::max(normal_error, 1 - std::abs(normal.dot(n)));
      plane_distance = std::max(plane_distance, std::abs(n.dot(p) - 2.0));
    }
    EXPECT_EQ(with_normal, long(s.width - 2) * (s.height - 2));
    EXPECT_LT(normal_error, 1e-6) << s.width;
    // Level 1 holds a measured depth of each 2x2 block (the lower median), not the centre's.
    EXPECT_LT(plane_distance, s.width == cam.width ? 1e-5 : 1e-3) << s.width;
  }
  // Smoothing keeps a plane's normal away from the border, where the filter reflects the image.
  const Surface smoothed = make_surface_pyramid(plane_depth(cam, n, 2.0), cam, {})[0];
  for (int v = 8; v < cam.height - 8; v += 7)
    for (int u = 8; u < cam.width - 8; u += 7)
      EXPECT_LT(1 - std::abs(normal_at(smoothed, u, v).dot(n)), 1e-5) << u << " " << v;
}

TEST(SurfacePyramid, NoNormalAcrossADepthEdgeOrAHole) {
  const Camera cam = Camera::freiburg3();
  cv::Mat depth(cam.height, cam.width, CV_32F, cv::Scalar(2.0));
  depth.colRange(320, 640).setTo(3.0);  // an edge between columns 319 and 320
  depth.at<float>(100, 100) = 0;        // a hole
  const Surface s = make_surface_pyramid(depth, cam, PointToPlaneSettings{})[0];
  EXPECT_FALSE(s.has_normal(s.index(319, 240)));
  EXPECT_FALSE(s.has_normal(s.index(320, 240)));
  EXPECT_TRUE(s.has_normal(s.index(318, 240)));
  EXPECT_TRUE(std::isnan(s.point(s.index(100, 100)).z()));  // no measurement, no point
  EXPECT_FALSE(s.has_normal(s.index(101, 100)));            // its neighbour misses one
  EXPECT_FALSE(s.has_normal(s.index(0, 240)));              // the border has no left neighbour
}

TEST(SurfacePyramid, SameSurfacesWhateverTheThreadCount) {
  const Camera cam = Camera::freiburg3();
  cv::Mat depth = plane_depth(cam, Eigen::Vector3d(0.1, 0.4, 1).normalized(), 1.5);
  cv::randn(depth.rowRange(200, 300), 1.4, 0.01);  // noise for the bilateral filter to smooth
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const Surface one = make_surface_pyramid(depth, cam, PointToPlaneSettings{})[0];
  omp_set_num_threads(3);
  const Surface three = make_surface_pyramid(depth, cam, PointToPlaneSettings{})[0];
  omp_set_num_threads(threads);
  ASSERT_EQ(one.pixels.size(), three.pixels.size());
  EXPECT_EQ(0, std::memcmp(one.pixels.data(), three.pixels.data(),
                           size_t(one.pixels.size()) * sizeof(float)));  // NaN for NaN too
}

}  // namespace
}  // namespace slamkit
