#include "bin/python/trajectory_arrays.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace slamkit::python {
namespace {

namespace py = pybind11;

[[noreturn]] void fail(const std::string& text) { throw std::invalid_argument(text); }

std::string shape_text(const Array& a) {
  std::string text = "(";
  for (py::ssize_t d = 0; d < a.ndim(); ++d) text += (d ? ", " : "") + std::to_string(a.shape(d));
  return text + (a.ndim() == 1 ? ",)" : ")");
}

// The row count of `a`, which must be (N, columns...) with N = `rows` (or any N when rows < 0).
size_t require_shape(const Array& a, const char* name, std::vector<py::ssize_t> columns,
                     py::ssize_t rows) {
  bool ok = a.ndim() == static_cast<py::ssize_t>(columns.size() + 1);
  for (size_t d = 0; ok && d < columns.size(); ++d) ok = a.shape(d + 1) == columns[d];
  if (ok && rows >= 0) ok = a.shape(0) == rows;
  if (!ok) {
    std::string want = "(" + (rows >= 0 ? std::to_string(rows) : std::string("N"));
    for (py::ssize_t c : columns) want += ", " + std::to_string(c);
    fail(std::string(name) + " must have shape " + want + (columns.empty() ? ",)" : ")") +
         ", not " + shape_text(a));
  }
  return static_cast<size_t>(a.shape(0));
}

void require_finite_rows(const Array& a, const char* name) {
  const size_t n = static_cast<size_t>(a.size());
  const size_t per_row = a.shape(0) ? n / static_cast<size_t>(a.shape(0)) : 1;
  const double* v = a.data();
  for (size_t k = 0; k < n; ++k)
    if (!std::isfinite(v[k]) || std::abs(v[k]) > kMaxTrajectoryValue)
      fail(std::string(name) + "[" + std::to_string(k / per_row) + "] holds " +
           std::to_string(v[k]) + ": values must be finite and within 1e100");
}

// Puts `v` in `order`.
template <class T>
std::vector<T> permuted(const std::vector<T>& v, const std::vector<size_t>& order) {
  std::vector<T> out;
  out.reserve(order.size());
  for (size_t k : order) out.push_back(v[k]);
  return out;
}

// Orders the poses by stamp (stably) and refuses a repeated stamp, which the file reader would
// resolve by a rule (--duplicate-stamps) that arrays do not carry. Sorted input (the usual case)
// is moved, not copied: a million poses cost milliseconds.
std::shared_ptr<TrajectoryFile> build(std::vector<double> stamps,
                                      std::vector<Eigen::Vector3d> positions,
                                      std::vector<Eigen::Quaterniond> orientations) {
  if (stamps.empty()) fail("a trajectory needs at least one pose");
  auto file = std::make_shared<TrajectoryFile>();
  std::vector<size_t> order;  // row of each sorted pose, when reordered
  file->was_unsorted = !std::is_sorted(stamps.begin(), stamps.end());
  if (file->was_unsorted) {
    order.resize(stamps.size());
    std::iota(order.begin(), order.end(), size_t{0});
    std::stable_sort(order.begin(), order.end(),
                     [&](size_t a, size_t b) { return stamps[a] < stamps[b]; });
    stamps = permuted(stamps, order);
    positions = permuted(positions, order);
    orientations = permuted(orientations, order);
  }
  for (size_t k = 1; k < stamps.size(); ++k)
    if (stamps[k] == stamps[k - 1])
      fail("stamps[" + std::to_string(order.empty() ? k : order[k]) + "] repeats the stamp " +
           std::to_string(stamps[k]) + ": each pose needs its own time");
  file->trajectory = Trajectory(std::move(stamps), std::move(positions), std::move(orientations));
  return file;
}

}  // namespace

std::shared_ptr<TrajectoryFile> trajectory_from_quaternions(const Array& stamps,
                                                            const Array& positions,
                                                            const Array& quaternions) {
  const auto n = static_cast<py::ssize_t>(require_shape(stamps, "stamps", {}, -1));
  require_shape(positions, "positions", {3}, n);
  require_shape(quaternions, "quaternions", {4}, n);
  require_finite_rows(stamps, "stamps");
  require_finite_rows(positions, "positions");
  require_finite_rows(quaternions, "quaternions");
  const double* t = positions.data();
  const double* qv = quaternions.data();
  std::vector<Eigen::Vector3d> p(static_cast<size_t>(n));
  std::vector<Eigen::Quaterniond> q(static_cast<size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) {
    p[i] = Eigen::Vector3d(t[3 * i], t[3 * i + 1], t[3 * i + 2]);
    q[i] = Eigen::Quaterniond(qv[4 * i + 3], qv[4 * i], qv[4 * i + 1], qv[4 * i + 2]);
    if (q[i].squaredNorm() == 0)
      fail("quaternions[" + std::to_string(i) + "] is zero: not a rotation");
    q[i].normalize();
  }
  return build(std::vector<double>(stamps.data(), stamps.data() + n), std::move(p), std::move(q));
}

std::shared_ptr<TrajectoryFile> trajectory_from_poses(const Array& stamps, const Array& poses) {
  const auto n = static_cast<py::ssize_t>(require_shape(stamps, "stamps", {}, -1));
  require_shape(poses, "poses", {4, 4}, n);
  require_finite_rows(stamps, "stamps");
  require_finite_rows(poses, "poses");
  const double* m = poses.data();
  std::vector<Eigen::Vector3d> p(static_cast<size_t>(n));
  std::vector<Eigen::Quaterniond> q(static_cast<size_t>(n));
  for (py::ssize_t i = 0; i < n; ++i) {
    const Eigen::Matrix4d T =
        Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(m + 16 * i);
    const Eigen::Matrix3d R = T.topLeftCorner<3, 3>();
    // Rigid to the precision of a 4x4 printed with 9 digits; anything else is not a pose.
    const bool rigid =
        (R.transpose() * R - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() < 1e-6 &&
        R.determinant() > 0 && T.row(3).isApprox(Eigen::RowVector4d(0, 0, 0, 1));
    if (!rigid)
      fail("poses[" + std::to_string(i) +
           "] is not a rigid transform (an orthonormal rotation with determinant 1 and last row 0 "
           "0 0 1)");
    p[i] = T.topRightCorner<3, 1>();
    q[i] = Eigen::Quaterniond(R).normalized();
  }
  return build(std::vector<double>(stamps.data(), stamps.data() + n), std::move(p), std::move(q));
}

Array stamps_array(const Trajectory& t) {
  Array a(static_cast<py::ssize_t>(t.size()));
  std::copy(t.stamps().begin(), t.stamps().end(), a.mutable_data());
  return a;
}

Array poses_array(const Trajectory& t) {
  Array a({static_cast<py::ssize_t>(t.size()), py::ssize_t{4}, py::ssize_t{4}});
  double* out = a.mutable_data();
  for (size_t i = 0; i < t.size(); ++i)
    Eigen::Map<Eigen::Matrix<double, 4, 4, Eigen::RowMajor>>(out + 16 * i) = t.pose(i).matrix();
  return a;
}

Array positions_array(const Trajectory& t) {
  Array a({static_cast<py::ssize_t>(t.size()), py::ssize_t{3}});
  double* out = a.mutable_data();
  for (size_t i = 0; i < t.size(); ++i) Eigen::Map<Eigen::Vector3d>(out + 3 * i) = t.position(i);
  return a;
}

Array quaternions_array(const Trajectory& t) {
  Array a({static_cast<py::ssize_t>(t.size()), py::ssize_t{4}});
  double* out = a.mutable_data();
  for (size_t i = 0; i < t.size(); ++i) {
    const Eigen::Quaterniond q = t.orientation(i);
    out[4 * i] = q.x();
    out[4 * i + 1] = q.y();
    out[4 * i + 2] = q.z();
    out[4 * i + 3] = q.w();
  }
  return a;
}

}  // namespace slamkit::python
