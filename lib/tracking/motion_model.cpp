#include "tracking/motion_model.h"

#include <cmath>
#include <stdexcept>

namespace slamkit {
namespace {

Eigen::Matrix3d hat(const Eigen::Vector3d& w) {
  Eigen::Matrix3d W;
  W << 0, -w.z(), w.y(), w.z(), 0, -w.x(), -w.y(), w.x(), 0;
  return W;
}

Eigen::Vector3d log_so3(const Eigen::Matrix3d& R) {
  const Eigen::AngleAxisd aa(R);
  return aa.angle() * aa.axis();
}

Eigen::Matrix3d exp_so3(const Eigen::Vector3d& w) {
  const double angle = w.norm();
  return angle > 0 ? Eigen::AngleAxisd(angle, w / angle).matrix() : Eigen::Matrix3d::Identity();
}

// Left Jacobian of SO(3): the translation of exp((rho, w)) is V(w) rho.
Eigen::Matrix3d se3_v(const Eigen::Vector3d& w) {
  const double theta = w.norm();
  const Eigen::Matrix3d W = hat(w);
  if (theta < 1e-5) return Eigen::Matrix3d::Identity() + 0.5 * W + W * W / 6;  // series
  const double t2 = theta * theta;
  return Eigen::Matrix3d::Identity() + (1 - std::cos(theta)) / t2 * W +
         (theta - std::sin(theta)) / (t2 * theta) * W * W;
}

}  // namespace

StampedVelocity velocity_between(const StampedPose& a, const StampedPose& b) {
  const double dt = b.stamp - a.stamp;
  if (!(dt > 0)) throw std::invalid_argument("velocity_between: stamps not increasing");
  StampedVelocity v;
  v.stamp = 0.5 * (a.stamp + b.stamp);
  v.linear = (b.T_w_c.translation() - a.T_w_c.translation()) / dt;
  v.angular = log_so3(a.T_w_c.linear().transpose() * b.T_w_c.linear()) / dt;
  return v;
}

StampedVelocity extrapolate_velocity(const StampedVelocity& older, const StampedVelocity& newer,
                                     double t) {
  const double span = newer.stamp - older.stamp;
  StampedVelocity v = newer;
  v.stamp = t;
  if (span == 0) return v;  // one sample: constant velocity
  const double s = (t - newer.stamp) / span;
  v.linear += s * (newer.linear - older.linear);
  v.angular += s * (newer.angular - older.angular);
  return v;
}

Eigen::Isometry3d integrate_velocity(const StampedPose& last, const StampedVelocity& v, double t) {
  const double dt = t - last.stamp;
  Eigen::Isometry3d T = last.T_w_c;
  T.translation() += v.linear * dt;
  T.linear() = last.T_w_c.linear() * exp_so3(v.angular * dt);
  return T;
}

Eigen::Isometry3d predict_linear_velocity(const StampedVelocity& older,
                                          const StampedVelocity& newer, const StampedPose& last,
                                          double t) {
  // With a velocity linear in time, the mean velocity over [t_last, t] is the one at the
  // midpoint: integrating it is exact, not a first-order step.
  const StampedVelocity mid = extrapolate_velocity(older, newer, 0.5 * (last.stamp + t));
  return integrate_velocity(last, mid, t);
}

Eigen::Isometry3d predict_constant_velocity(const StampedPose& prev, const StampedPose& last,
                                            double t) {
  const double span = last.stamp - prev.stamp;
  if (span == 0) return last.T_w_c;
  const double s = (t - last.stamp) / span;
  const Eigen::Isometry3d delta = prev.T_w_c.inverse() * last.T_w_c;
  const Eigen::Vector3d w = log_so3(delta.linear());
  const Eigen::Vector3d rho = se3_v(w).inverse() * delta.translation();
  Eigen::Isometry3d step = Eigen::Isometry3d::Identity();
  step.linear() = exp_so3(s * w);
  step.translation() = se3_v(s * w) * (s * rho);
  return last.T_w_c * step;
}

}  // namespace slamkit
