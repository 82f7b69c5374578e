#include "optimization/pose_graph.h"

#include <ceres/autodiff_cost_function.h>
#include <ceres/manifold.h>
#include <ceres/problem.h>
#include <ceres/solver.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace slamkit {
namespace {

// The residual of one edge: the estimated relative pose T_from^-1 T_to against the measured
// one, as (translation difference in `from`'s frame, 2 vec(q_measured^-1 q_estimated)), scaled
// by sqrt(weight). Parameters: q_from, t_from, q_to, t_to (world-from-camera; quaternions as
// Eigen's x, y, z, w).
struct RelativePoseResidual {
  RelativePoseResidual(const Eigen::Isometry3d& T_from_to, double weight)
      : t_measured(T_from_to.translation()),
        q_measured(Eigen::Quaterniond(T_from_to.linear()).normalized()),
        scale(std::sqrt(weight)) {}

  template <class T>
  bool operator()(const T* q_from_data, const T* t_from_data, const T* q_to_data,
                  const T* t_to_data, T* residual_data) const {
    const Eigen::Map<const Eigen::Quaternion<T>> q_from(q_from_data), q_to(q_to_data);
    const Eigen::Map<const Eigen::Matrix<T, 3, 1>> t_from(t_from_data), t_to(t_to_data);
    const Eigen::Quaternion<T> q_from_inverse = q_from.conjugate();
    const Eigen::Quaternion<T> q_estimated = q_from_inverse * q_to;
    const Eigen::Matrix<T, 3, 1> t_estimated = q_from_inverse * (t_to - t_from);
    const Eigen::Quaternion<T> q_error = q_measured.template cast<T>().conjugate() * q_estimated;
    Eigen::Map<Eigen::Matrix<T, 6, 1>> residual(residual_data);
    residual.template head<3>() = t_estimated - t_measured.template cast<T>();
    residual.template tail<3>() = T(2.0) * q_error.vec();
    residual *= T(scale);
    return true;
  }

  Eigen::Vector3d t_measured;
  Eigen::Quaterniond q_measured;
  double scale;
};

}  // namespace

PoseGraphReport optimise_pose_graph(PoseGraph& graph, int iterations) {
  const int n = int(graph.T_w_c.size());
  if (int(graph.fixed.size()) != n)
    throw std::invalid_argument("pose graph: " + std::to_string(graph.fixed.size()) +
                                " fixed flags for " + std::to_string(n) + " nodes");
  for (const PoseGraphEdge& e : graph.edges)
    if (e.from < 0 || e.from >= n || e.to < 0 || e.to >= n || e.from == e.to)
      throw std::invalid_argument("pose graph: edge " + std::to_string(e.from) + " -> " +
                                  std::to_string(e.to) + " does not join two of the " +
                                  std::to_string(n) + " nodes");
  PoseGraphReport report;
  bool any_free = false;
  for (bool fixed : graph.fixed) any_free = any_free || !fixed;
  if (!any_free || graph.edges.empty() || iterations <= 0) return report;

  // One array (per node: quaternion x, y, z, w, then translation): blocks in index order.
  std::vector<double> parameters(7 * size_t(n));
  for (int i = 0; i < n; ++i) {
    Eigen::Map<Eigen::Quaterniond> q(&parameters[7 * size_t(i)]);
    Eigen::Map<Eigen::Vector3d> t(&parameters[7 * size_t(i) + 4]);
    q = Eigen::Quaterniond(graph.T_w_c[size_t(i)].linear()).normalized();
    t = graph.T_w_c[size_t(i)].translation();
  }
  ceres::Problem problem;
  std::vector<bool> added(size_t(n), false);
  const auto add_node = [&](int i) {
    if (added[size_t(i)]) return;
    added[size_t(i)] = true;
    double* q = &parameters[7 * size_t(i)];
    problem.AddParameterBlock(q, 4, new ceres::EigenQuaternionManifold);
    problem.AddParameterBlock(q + 4, 3);
    if (graph.fixed[size_t(i)]) {
      problem.SetParameterBlockConstant(q);
      problem.SetParameterBlockConstant(q + 4);
    }
  };
  for (const PoseGraphEdge& e : graph.edges) {
    add_node(e.from);
    add_node(e.to);
    double* from = &parameters[7 * size_t(e.from)];
    double* to = &parameters[7 * size_t(e.to)];
    problem.AddResidualBlock(
        new ceres::AutoDiffCostFunction<RelativePoseResidual, 6, 4, 3, 4, 3>(
            new RelativePoseResidual(e.T_from_to, e.weight)),
        nullptr, from, from + 4, to, to + 4);
  }
  ceres::Solver::Options options;
  options.max_num_iterations = iterations;
  options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;  // a chain with a few loops
  options.num_threads = 1;                                     // bit-reproducible sums
  options.logging_type = ceres::SILENT;
  ceres::Solver::Summary summary;
  ceres::Solve(options, &problem, &summary);
  if (!summary.IsSolutionUsable()) return report;

  for (int i = 0; i < n; ++i) {
    if (graph.fixed[size_t(i)]) continue;
    const Eigen::Quaterniond q =
        Eigen::Map<const Eigen::Quaterniond>(&parameters[7 * size_t(i)]).normalized();
    graph.T_w_c[size_t(i)].linear() = q.toRotationMatrix();
    graph.T_w_c[size_t(i)].translation() =
        Eigen::Map<const Eigen::Vector3d>(&parameters[7 * size_t(i) + 4]);
  }
  report.solved = true;
  report.iterations = summary.num_linear_solves;
  report.initial_cost = summary.initial_cost;
  report.final_cost = summary.final_cost;
  return report;
}

}  // namespace slamkit
