#pragma once
// Synthetic bundle-adjustment problems with a known answer: cameras along a line looking
// forward, each point seen by the cameras nearest to the one it was placed in front of (its
// anchor). About half the observations have depth, the anchor's always.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <ctime>
#include <random>
#include <vector>

#include "optimization/bundle_adjustment.h"

namespace slamkit {

struct TestSceneOptions {
  int num_poses = 6;
  int num_points = 300;
  int views_per_point = 4;
  double camera_spacing = 0.05;  // metres between consecutive cameras along x
  double depth_fraction = 0.4;   // share of the other views with a depth measurement
  double pixel_noise = 0;        // standard deviation in units of the observation's sigma
  unsigned seed = 1;
};

struct TestScene {
  BaProblem truth;  // exact poses and points; observations as measured
  BaIntrinsics intrinsics{520, 520, 320, 240};
  BaResidualSettings residual;
};

inline Eigen::Isometry3d test_rotation(const Eigen::Vector3d& axis_angle) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  if (axis_angle.norm() > 0) {
    T.linear() = Eigen::AngleAxisd(axis_angle.norm(), axis_angle.normalized()).toRotationMatrix();
  }
  return T;
}

inline TestScene make_test_scene(const TestSceneOptions& options) {
  TestScene scene;
  BaProblem& problem = scene.truth;
  const BaIntrinsics& k = scene.intrinsics;
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::normal_distribution<double> normal(0, 1);
  for (int i = 0; i < options.num_poses; ++i) {
    // Camera i at (spacing i, 0, 0), looking along +z with a few degrees of wobble.
    Eigen::Isometry3d T_w_c =
        test_rotation(0.05 * Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)));
    T_w_c.translation() = Eigen::Vector3d(options.camera_spacing * i, 0.02 * uniform(rng), 0);
    problem.T_c_w.push_back(T_w_c.inverse());
    problem.pose_fixed.push_back(false);
  }
  const auto project = [&](int pose, const Eigen::Vector3d& p_w, Eigen::Vector2d& uv, double& z) {
    const Eigen::Vector3d p_c = problem.T_c_w[pose] * p_w;
    z = p_c.z();
    uv = Eigen::Vector2d(k.fx * p_c.x() / z + k.cx, k.fy * p_c.y() / z + k.cy);
    return z > 0.1 && uv.x() >= 0 && uv.x() < 640 && uv.y() >= 0 && uv.y() < 480;
  };
  std::uniform_int_distribution<int> pose_of(0, options.num_poses - 1);
  std::uniform_int_distribution<int> octave_of(0, 3);
  for (int j = 0; j < options.num_points; ++j) {
    // A point in front of a random camera, inside its image, 1.5 to 5 m away.
    const int anchor = pose_of(rng);
    const double z = 3.25 + 1.75 * uniform(rng);
    const Eigen::Vector3d p_c(0.45 * z * uniform(rng), 0.45 * z * uniform(rng), z);
    problem.p_w.push_back(problem.T_c_w[anchor].inverse() * p_c);
    int views = 0;
    // Cameras by distance in index from the anchor: anchor, +1, -1, +2, -2, ...
    for (int step = 0; step < 2 * options.num_poses && views < options.views_per_point; ++step) {
      const int pose = anchor + (step % 2 == 0 ? step / 2 : -(step + 1) / 2);
      Eigen::Vector2d uv;
      double depth;
      if (pose < 0 || pose >= options.num_poses || !project(pose, problem.p_w[j], uv, depth)) {
        continue;
      }
      BaObservation o;
      o.pose = pose;
      o.point = j;
      o.sigma = std::pow(1.2, octave_of(rng));
      o.uv = uv + options.pixel_noise * o.sigma * Eigen::Vector2d(normal(rng), normal(rng));
      // The anchor view always has depth, as a map point is created from a keyframe's depth.
      if (pose == anchor || (uniform(rng) + 1) / 2 < options.depth_fraction) {
        // Noise on the disparity bf / z, as the residual measures it.
        const double bf = scene.residual.virtual_bf;
        o.depth = bf / (bf / depth + options.pixel_noise * o.sigma * normal(rng));
      }
      problem.observations.push_back(o);
      ++views;
    }
  }
  return scene;
}

// Free poses moved by up to `metres` and `radians`, every point by up to `point_metres`.
inline BaProblem perturbed(const BaProblem& truth, double metres, double radians,
                           double point_metres, unsigned seed = 7) {
  BaProblem problem = truth;
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  const auto random_vector = [&]() {
    return Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng)).normalized();
  };
  for (size_t i = 0; i < problem.T_c_w.size(); ++i) {
    if (problem.pose_fixed[i]) continue;
    Eigen::Isometry3d delta = test_rotation(radians * random_vector());
    delta.translation() = metres * random_vector();
    problem.T_c_w[i] = delta * problem.T_c_w[i];
  }
  for (Eigen::Vector3d& p : problem.p_w) p += point_metres * random_vector();
  return problem;
}

// Largest camera-centre distance (metres) and rotation difference (degrees) between poses.
struct PoseErrors {
  double metres = 0;
  double degrees = 0;
};

inline PoseErrors max_pose_errors(const BaProblem& a, const BaProblem& b) {
  PoseErrors errors;
  for (size_t i = 0; i < a.T_c_w.size(); ++i) {
    const Eigen::Vector3d centre_a = a.T_c_w[i].inverse().translation();
    const Eigen::Vector3d centre_b = b.T_c_w[i].inverse().translation();
    errors.metres = std::max(errors.metres, (centre_a - centre_b).norm());
    const double angle =
        Eigen::AngleAxisd(a.T_c_w[i].linear().transpose() * b.T_c_w[i].linear()).angle();
    errors.degrees = std::max(errors.degrees, angle * 180 / M_PI);
  }
  return errors;
}

// CPU time of the calling thread: timings stay meaningful on a machine busy with other work.
inline double thread_cpu_seconds() {
  timespec t;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return t.tv_sec + 1e-9 * t.tv_nsec;
}

inline double max_point_error(const BaProblem& a, const BaProblem& b) {
  double error = 0;
  for (size_t j = 0; j < a.p_w.size(); ++j) error = std::max(error, (a.p_w[j] - b.p_w[j]).norm());
  return error;
}

// Bit for bit: the same doubles, not merely close ones.
inline bool bit_identical(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return std::memcmp(a.matrix().data(), b.matrix().data(), sizeof(double) * 16) == 0;
}

inline bool bit_identical_points(const BaProblem& a, const BaProblem& b) {
  return a.p_w.size() == b.p_w.size() &&
         std::memcmp(a.p_w.data(), b.p_w.data(), sizeof(Eigen::Vector3d) * a.p_w.size()) == 0;
}

inline bool bit_identical(const BaProblem& a, const BaProblem& b) {
  if (a.T_c_w.size() != b.T_c_w.size()) return false;
  for (size_t i = 0; i < a.T_c_w.size(); ++i)
    if (!bit_identical(a.T_c_w[i], b.T_c_w[i])) return false;
  return bit_identical_points(a, b);
}

}  // namespace slamkit
