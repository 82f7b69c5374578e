// The TSDF map on scenes whose surface is known exactly: a plane and a sphere rendered as
// depth images from known poses. The surface points lie on them, the normals face the
// cameras, the mesh is closed and turned outwards, depth edges and flying pixels do not become
// surface, and the output is the same at any thread count.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <map>
#include <optional>

#include "core/camera.h"
#include "fusion/tsdf_frame.h"
#include "fusion/tsdf_surface.h"
#include "fusion/tsdf_volume.h"

namespace slamkit {
namespace {

Camera test_camera() {
  Camera camera;
  camera.fx = camera.fy = 525;
  camera.cx = 319.5;
  camera.cy = 239.5;
  return camera;
}

// Where the ray of raw pixel (u, v) from a camera at T_w_c first meets the scene, as depth
// along the optical axis (0: it meets nothing).
using Scene = std::function<double(const Eigen::Vector3d& origin, const Eigen::Vector3d& ray)>;

double sphere_hit(const Eigen::Vector3d& centre, double radius, const Eigen::Vector3d& origin,
                  const Eigen::Vector3d& direction) {
  const Eigen::Vector3d oc = origin - centre;
  const double b = oc.dot(direction), c = oc.squaredNorm() - radius * radius;
  const double disc = b * b - c;
  if (disc < 0) return 0;
  const double t = -b - std::sqrt(disc);
  return t > 0 ? t : 0;
}

FusionSamples render(const Camera& camera, const Eigen::Isometry3d& T_w_c, const Scene& scene,
                     int stride) {
  FusionSamples samples;
  for (int v = 0; v < camera.height; v += stride)
    for (int u = 0; u < camera.width; u += stride) {
      const Eigen::Vector3d ray_c((u - camera.cx) / camera.fx, (v - camera.cy) / camera.fy, 1);
      const Eigen::Vector3d direction = (T_w_c.linear() * ray_c).normalized();
      const double t = scene(T_w_c.translation(), direction);
      samples.depth.push_back(float(t * direction.dot(T_w_c.linear().col(2))));
      samples.bgr.emplace_back(uint8_t(u % 256), uint8_t(v % 256), 200);
    }
  return samples;
}

// A camera at `eye` looking at `target` (y of the image roughly down).
Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target) {
  const Eigen::Vector3d z = (target - eye).normalized();
  const Eigen::Vector3d x = Eigen::Vector3d::UnitY().cross(z).normalized();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() << x, z.cross(x), z;
  T.translation() = eye;
  return T;
}

FusionSettings noiseless_settings() {
  FusionSettings settings;
  settings.pixel_stride = 2;
  return settings;
}

const Eigen::Vector3d kCentre(0.1, -0.05, 1.2);
constexpr double kRadius = 0.3;

// The sphere seen from ten cameras around it at 1 m.
TsdfVolume sphere_volume(const FusionSettings& settings) {
  const Camera camera = test_camera();
  const TsdfFrameMaker maker(camera, settings);
  TsdfVolume volume(float(settings.voxel_size), float(settings.truncation));
  const Scene sphere = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    return sphere_hit(kCentre, kRadius, o, d);
  };
  std::vector<Eigen::Vector3d> eyes = {kCentre + Eigen::Vector3d(0.1, -1, 0),
                                       kCentre + Eigen::Vector3d(-0.1, 1, 0)};  // above, below
  for (int k = 0; k < 8; ++k) {
    const double a = 2 * M_PI * k / 8;
    eyes.push_back(kCentre + Eigen::Vector3d(std::sin(a), 0.3 * std::cos(3 * a), -std::cos(a)));
  }
  for (const Eigen::Vector3d& eye : eyes) {
    const Eigen::Isometry3d pose = look_at(eye, kCentre);
    volume.integrate(maker.make(render(camera, pose, sphere, settings.pixel_stride)), pose);
  }
  return volume;
}

TEST(Tsdf, PlaneSeenHeadOnIsItsSurfaceWithNormalsTowardsTheCamera) {
  const FusionSettings settings = noiseless_settings();
  const Camera camera = test_camera();
  const TsdfFrameMaker maker(camera, settings);
  TsdfVolume volume(float(settings.voxel_size), float(settings.truncation));
  const Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const Scene wall = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    return (1.234 - o.z()) / d.z();
  };
  volume.integrate(maker.make(render(camera, pose, wall, settings.pixel_stride)), pose);
  const PlyCloud surface = extract_surface(volume, 0, false);
  ASSERT_GT(surface.points.size(), 10000u);
  for (size_t i = 0; i < surface.points.size(); ++i) {
    ASSERT_NEAR(surface.points[i].z(), 1.234, 1e-4) << i;
    ASSERT_LT((surface.normals[i] - Eigen::Vector3f(0, 0, -1)).norm(), 1e-3) << i;
    ASSERT_EQ(surface.colours[i][0], 200) << i;  // red, sampled as BGR
  }
}

TEST(Tsdf, SphereSurfaceLiesOnTheSphereAndItsMeshIsClosedAndTurnedOutwards) {
  const PlyCloud mesh = extract_surface(sphere_volume(noiseless_settings()), 0, true);
  ASSERT_GT(mesh.points.size(), 5000u);
  double worst = 0, sum = 0;
  for (size_t i = 0; i < mesh.points.size(); ++i) {
    const Eigen::Vector3d p = mesh.points[i].cast<double>();
    const double error = std::abs((p - kCentre).norm() - kRadius);
    worst = std::max(worst, error);
    sum += error;
    EXPECT_GT(mesh.normals[i].cast<double>().dot((p - kCentre).normalized()), 0.95) << i;
  }
  // Linear interpolation of a distance measured along the optical axis, on a curved surface
  // seen obliquely at its rim: within a fifth of a 1 cm voxel, a twentieth on average.
  EXPECT_LT(worst, 0.002);
  EXPECT_LT(sum / double(mesh.points.size()), 0.0005) << sum / double(mesh.points.size());

  ASSERT_GT(mesh.triangles.size(), 5000u);
  std::map<std::pair<uint32_t, uint32_t>, int> edge_uses;
  size_t outwards = 0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d a = mesh.points[t[0]].cast<double>(), b = mesh.points[t[1]].cast<double>(),
                          c = mesh.points[t[2]].cast<double>();
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    if (normal.dot((a + b + c) / 3 - kCentre) > 0) ++outwards;
    for (int e = 0; e < 3; ++e) {
      const uint32_t from = t[size_t(e)], to = t[size_t((e + 1) % 3)];
      ++edge_uses[{std::min(from, to), std::max(from, to)}];
    }
  }
  EXPECT_GE(outwards, mesh.triangles.size() * 99 / 100);
  // Seen all around: every edge joins two triangles (a closed surface).
  size_t open = 0;
  for (const auto& [edge, uses] : edge_uses) open += uses != 2;
  EXPECT_LT(open, edge_uses.size() / 100) << open << " of " << edge_uses.size();

  const PlyCloud compact = referenced_vertices(mesh);
  EXPECT_EQ(compact.triangles.size(), mesh.triangles.size());
  EXPECT_LE(compact.points.size(), mesh.points.size());
  for (size_t k = 0; k < 100; ++k)
    for (int c = 0; c < 3; ++c)
      EXPECT_EQ(compact.points[compact.triangles[k][size_t(c)]],
                mesh.points[mesh.triangles[k][size_t(c)]]);
}

TEST(Tsdf, DepthEdgesAndFlyingPixelsDoNotBecomeSurface) {
  // A box face at 1 m in front of a wall at 1.6 m; along the box's edges the depth jumps, and
  // a column of flying pixels lies halfway between the two.
  const FusionSettings settings = noiseless_settings();
  const Camera camera = test_camera();
  const TsdfFrameMaker maker(camera, settings);
  TsdfVolume volume(float(settings.voxel_size), float(settings.truncation));
  const Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  const Scene box_on_wall = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    const double t_box = (1.0 - o.z()) / d.z();
    const Eigen::Vector3d p = o + t_box * d;
    if (std::abs(p.x()) < 0.2 && std::abs(p.y()) < 0.2) return t_box;
    return (1.6 - o.z()) / d.z();
  };
  FusionSamples samples = render(camera, pose, box_on_wall, settings.pixel_stride);
  const int width = 320;
  int flying = 0;
  for (int j = 0; j < 240; ++j)
    for (int i = 1; i < width; ++i) {
      const size_t k = size_t(j * width + i);
      if (samples.depth[k - 1] < 1.1f && samples.depth[k] > 1.5f) {  // the box's right edge
        samples.depth[k] = 1.3f;
        ++flying;
      }
    }
  ASSERT_GT(flying, 50);
  const TsdfFrame frame = maker.make(samples);
  volume.integrate(frame, pose);
  const PlyCloud surface = extract_surface(volume, 0, true);
  ASSERT_GT(surface.points.size(), 10000u);
  for (size_t i = 0; i < surface.points.size(); ++i) {
    const float z = surface.points[i].z();
    // On the box or the wall, within a millimetre; nothing in between.
    ASSERT_TRUE(std::abs(z - 1.0f) < 1e-3f || std::abs(z - 1.6f) < 1e-3f)
        << i << ": " << surface.points[i].transpose();
  }
}

TEST(Tsdf, NoiseWeightingFavoursNearAndHeadOnMeasurements) {
  const FusionSettings settings = noiseless_settings();
  const TsdfFrameMaker maker(test_camera(), settings);
  const Scene wall_at = [](const Eigen::Vector3d& o, const Eigen::Vector3d& d) {
    return (1.0 - o.z()) / d.z();
  };
  const TsdfFrame near = maker.make(render(test_camera(), Eigen::Isometry3d::Identity(), wall_at,
                                           settings.pixel_stride));
  Eigen::Isometry3d back = Eigen::Isometry3d::Identity();
  back.translation().z() = -1.0;  // the same wall at 2 m
  const TsdfFrame far = maker.make(render(test_camera(), back, wall_at, settings.pixel_stride));
  const size_t centre = size_t(120 * 320 + 160);
  // A head-on sample at 1 m weighs 1; at 2 m sigma is (0.0012 + 0.0019 * 1.6^2) / 0.001884.
  EXPECT_EQ(near.weight[centre], 256);
  const double sigma_ratio = (0.0012 + 0.0019 * 1.6 * 1.6) / (0.0012 + 0.0019 * 0.6 * 0.6);
  EXPECT_EQ(far.weight[centre], std::lround(256 / (sigma_ratio * sigma_ratio)));
  // Towards the image's corner the wall is seen obliquely: less weight at the same depth.
  EXPECT_LT(near.weight[0], near.weight[centre]);

  FusionSettings unweighted = settings;
  unweighted.noise_weighting = false;
  const TsdfFrame plain = TsdfFrameMaker(test_camera(), unweighted)
                              .make(render(test_camera(), back, wall_at, settings.pixel_stride));
  EXPECT_EQ(plain.weight[centre], 256);
}

TEST(Tsdf, SameSurfaceAndMeshAtOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const PlyCloud one = extract_surface(sphere_volume(noiseless_settings()), 0, true);
  omp_set_num_threads(2);
  const PlyCloud two = extract_surface(sphere_volume(noiseless_settings()), 0, true);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.normals, two.normals);
  EXPECT_EQ(one.colours, two.colours);
  EXPECT_EQ(one.triangles, two.triangles);
}

}  // namespace
}  // namespace slamkit
