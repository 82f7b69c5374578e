#include "eval/alignment.h"

#include <Eigen/Geometry>
#include <stdexcept>

#include "core/enum_names.h"

namespace slamkit::eval {

Eigen::Isometry3d Alignment::apply(const Eigen::Isometry3d& T_w_c) const {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotation * T_w_c.rotation();
  T.translation() = apply(Eigen::Vector3d(T_w_c.translation()));
  return T;
}

Alignment align(const std::vector<Eigen::Isometry3d>& est, const std::vector<Eigen::Isometry3d>& gt,
                AlignMethod method, size_t first_n) {
  if (est.size() != gt.size()) throw std::invalid_argument("align: pose lists differ in size");
  const size_t n = first_n == 0 ? est.size() : std::min(first_n, est.size());
  Alignment a;
  a.method = method;
  a.poses_used = method == AlignMethod::kNone ? 0 : n;
  if (method == AlignMethod::kNone || n == 0) return a;

  if (method == AlignMethod::kTranslation) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    for (size_t i = 0; i < n; ++i) sum += gt[i].translation() - est[i].translation();
    a.translation = sum / double(n);
    return a;
  }
  if (n == 1) {  // origin alignment: the first estimated pose onto the first groundtruth pose
    a.rotation = gt[0].rotation() * est[0].rotation().transpose();
    a.translation = gt[0].translation() - a.rotation * est[0].translation();
    return a;
  }
  if (n == 2)
    throw std::invalid_argument(
        "aligning on 2 poses leaves the rotation about their connecting line free; use "
        "--align-first 1 (origin) or at least 3");
  Eigen::Matrix3Xd src(3, n), dst(3, n);
  for (size_t i = 0; i < n; ++i) {
    src.col(i) = est[i].translation();
    dst.col(i) = gt[i].translation();
  }
  const Eigen::Matrix4d T = Eigen::umeyama(src, dst, method == AlignMethod::kSim3);
  // umeyama returns [s*R | t]; R has unit-norm columns, so s is the first column's norm.
  a.scale = method == AlignMethod::kSim3 ? T.block<3, 1>(0, 0).norm() : 1.0;
  a.rotation = T.block<3, 3>(0, 0) / a.scale;
  a.translation = T.block<3, 1>(0, 3);
  return a;
}

namespace {
constexpr EnumNames<AlignMethod, 4> kAlignNames = {{{AlignMethod::kSe3, "se3"},
                                                    {AlignMethod::kSim3, "sim3"},
                                                    {AlignMethod::kTranslation, "translation"},
                                                    {AlignMethod::kNone, "none"}}};
}  // namespace

std::string to_string(AlignMethod method) { return name_of(kAlignNames, method); }

AlignMethod parse_align_method(const std::string& text) {
  if (const auto method = value_named(kAlignNames, text)) return *method;
  throw std::invalid_argument("unknown alignment '" + text + "' (use " + choices(kAlignNames) + ")");
}

}  // namespace slamkit::eval
