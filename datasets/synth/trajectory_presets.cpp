#include "datasets/synth/trajectory_presets.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/error.h"
#include "datasets/synth/hand_shake.h"
#include "datasets/synth/multi_room_layouts.h"
#include "datasets/synth/room_layout.h"

namespace slamkit::synth {
namespace {

using Eigen::Vector3d;

constexpr double kDeg = M_PI / 180.0;
// Hand shake amplitudes (RMS): a few millimetres and a fraction of a degree.
constexpr double kShakeTranslation = 0.003, kShakeRotation = 0.35 * kDeg;

double wave(double t, double period_s, double phase = 0) {
  return std::sin(2 * M_PI * t / period_s + phase);
}

// 0 -> 1 with zero first and second derivatives at both ends.
double smootherstep(double x) {
  x = std::clamp(x, 0.0, 1.0);
  return x * x * x * (x * (6 * x - 15) + 10);
}

struct View {
  Vector3d eye, target;
};

Eigen::Isometry3d pose_of(const View& view) { return look_at(view.eye, view.target); }

// Hand-held sweeps on an arc south of the desk, about a metre away, looking at a point
// wandering over it: about 0.4 m/s and 30 deg/s on average, like TUM fr1/desk.
View desk_view(double t) {
  const double azimuth = 0.9 * wave(t, 14, 0.3) + 0.3 * wave(t, 5.3, 1.0);
  const double radius = 1.05 + 0.1 * wave(t, 7.7);
  const Vector3d eye(radius * std::sin(azimuth), -radius * std::cos(azimuth),
                     1.3 + 0.12 * wave(t, 9.1));
  return {eye, kDeskTopCentre + Vector3d(0.45 * wave(t, 3.9), 0.3 * wave(t, 5.7, 0.5),
                                         0.05 + 0.1 * wave(t, 4.3))};
}

// Around the desk on an ellipse, looking outwards at the walls with the yaw swinging 20 deg
// either side three times a lap, periodic in `phase` (0..1): each wall is seen only once a
// lap, the plain west one on depth alone, so tracking drifts and only the return to the start
// can correct it. At 150 frames it turns at up to 150 deg/s.
View loop_view(double phase) {
  const double a = 2 * M_PI * phase;
  const Vector3d eye(1.0 * std::cos(a), 0.75 * std::sin(a), 1.4 + 0.08 * std::sin(2 * a));
  const double yaw = a + 20 * kDeg * std::sin(3 * a), pitch = -15 * kDeg;
  return {eye, eye + Vector3d(std::cos(yaw), std::sin(yaw), std::tan(pitch))};
}

// A scripted path: keys (phase, eye, target) eased between (position lerped, orientation
// slerped, so turns are even; the camera slows to a stop at each key).
struct Key {
  double phase;
  Vector3d eye, target;
};

Eigen::Isometry3d keyed_pose(const std::vector<Key>& keys, double phase) {
  auto next = std::upper_bound(keys.begin(), keys.end(), phase,
                               [](double p, const Key& k) { return p < k.phase; });
  if (next == keys.end()) --next;
  if (next == keys.begin()) ++next;  // a phase before the first key (sensors sampling at t < 0)
  const Key& prev = *(next - 1);
  const double w = smootherstep((phase - prev.phase) / (next->phase - prev.phase));
  const Eigen::Quaterniond q0(look_at(prev.eye, prev.target).linear());
  const Eigen::Quaterniond q1(look_at(next->eye, next->target).linear());
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  T_w_c.linear() = q0.slerp(w, q1).toRotationMatrix();
  T_w_c.translation() = (1 - w) * prev.eye + w * next->eye;
  return T_w_c;
}

// Desk, then close to the plain corner for 40% of the sequence drifting slowly (so tracking
// has motion to follow on depth alone), then the sideboard.
Eigen::Isometry3d low_texture_pose(double phase) {
  static const std::vector<Key> kKeys = {
      {0.00, {-0.2, -1.4, 1.45}, {0.2, 0.1, 0.75}},
      {0.20, {-0.8, -1.0, 1.35}, {-0.3, 0.2, 0.8}},
      {0.32, {-1.35, 0.65, 1.15}, kPlainCorner + Vector3d(0, 0.15, 0.2)},
      {0.52, {-1.45, 0.45, 1.1}, kPlainCorner + Vector3d(0, 0.05, 0.15)},
      {0.72, {-1.4, 0.7, 1.2}, kPlainCorner + Vector3d(0, 0.2, 0.25)},
      {0.84, {-0.9, 0.9, 1.4}, {0.3, 1.8, 0.9}},
      {1.00, {-0.3, 0.8, 1.45}, {0.8, 1.9, 1.0}},
  };
  return keyed_pose(kKeys, phase);
}

// Through both rooms of two_rooms and back: round the first room looking at its walls, through
// the doorway, round the second room, back through the doorway and to the first pose.
Eigen::Isometry3d long_pose(double phase) {
  const Vector3d door(kDoorwayX, kDoorwayY, 1.45);
  const std::vector<Key> keys = {
      {0.00, {-0.3, -1.4, 1.45}, kDeskTopCentre},
      {0.07, {-1.3, -1.0, 1.4}, {-1.8, 0.9, 0.9}},
      {0.14, {-1.3, 0.9, 1.4}, {0.0, 1.9, 0.9}},
      {0.21, {0.4, 1.0, 1.45}, {2.5, 1.0, 1.4}},
      {0.28, door - Vector3d(1.15, 0, 0), door + Vector3d(1.5, 0, -0.45)},
      {0.35, door + Vector3d(1.05, 0, 0), kSecondRoomCentre + Vector3d(0, 0, 0.75)},
      {0.42, {4.0, -1.3, 1.45}, {5.5, -2.0, 1.3}},
      {0.49, {6.2, -1.0, 1.45}, {7.6, 0.0, 1.1}},
      {0.56, {6.4, 0.9, 1.45}, {5.0, 2.0, 0.7}},
      {0.63, {4.2, 1.0, 1.5}, {3.0, -0.5, 1.0}},
      {0.70, door + Vector3d(1.05, 0, 0), door - Vector3d(1.5, 0, 0.25)},
      {0.79, door - Vector3d(1.15, 0, 0), {-1.0, -1.2, 1.0}},
      {0.89, {0.8, -1.45, 1.45}, kDeskTopCentre + Vector3d(0.3, 0, 0)},
      {1.00, {-0.3, -1.4, 1.45}, kDeskTopCentre},
  };
  return keyed_pose(keys, phase);
}

// In twin_rooms: a look at the west room's desk, through the doorway to the same look at the
// east room's (the look-alike), and back to the first (a true revisit).
Eigen::Isometry3d lookalike_pose(double phase) {
  const Vector3d west = kFirstTwinCentre, east = kFirstTwinCentre + kTwinOffset;
  const Vector3d desk = kDeskTopCentre, door(0, kTwinDoorwayY, 1.45);
  const Vector3d look_eye(-0.2, -1.3, 1.45), aside_eye(0.3, -1.2, 1.4);
  const Vector3d aside_target(0.2, 0.3, 0.8);
  const std::vector<Key> keys = {
      {0.00, west + look_eye, west + desk},
      {0.10, west + aside_eye, west + aside_target},
      {0.22, door - Vector3d(1.2, 0, 0), door + Vector3d(1.5, 0, -0.35)},
      {0.34, door + Vector3d(1.2, 0, 0), east + Vector3d(0.95, -1.0, 1.0)},
      {0.46, east + aside_eye, east + aside_target},
      {0.56, east + look_eye, east + desk},
      {0.68, door + Vector3d(1.2, 0, 0), door - Vector3d(1.5, 0, 0.35)},
      {0.80, door - Vector3d(1.2, 0, 0), west + Vector3d(0.55, -1.0, 0.9)},
      {0.90, west + aside_eye, west + aside_target},
      {1.00, west + look_eye, west + desk},
  };
  return keyed_pose(keys, phase);
}

// Slow panning across the desk towards the north wall; the whip turns 40 deg right and moves
// 0.3 m right in two frames, then eases back over 2.5 s so relocalisation sees known places.
View jerk_view(double t, double whip) {
  constexpr double kWhipYaw = 40 * kDeg, kWhipShift = 0.3, kPitch = -20 * kDeg;
  const double yaw = 0.5 * wave(t, 8, 0.5) - whip * kWhipYaw;  // 0 faces +y, positive left
  const Vector3d eye(0.3 + 0.35 * wave(t, 9) + whip * kWhipShift, -1.45 + 0.1 * wave(t, 6.5),
                     1.4 + 0.08 * wave(t, 5));
  return {eye, eye + Vector3d(-std::sin(yaw), std::cos(yaw), std::tan(kPitch))};
}

constexpr double kEaseBack = 2.5;  // seconds the jerk's whip takes to ease back

double whip_weight(int i, int frames) {
  const int start = jerk_whip_frame(frames);
  if (i <= start) return 0;
  if (i == start + 1) return 0.5;
  return 1 - smootherstep((i - start - 2) / kFrameRate / kEaseBack);
}

// The whip between frames, for sensors sampling there: linear through the two whip steps (0,
// 0.5, 1 at frames start, start + 1, start + 2), then the same ease back; equal to
// whip_weight at frame times.
double whip_weight_at(double t, int frames) {
  const double steps = t * kFrameRate - jerk_whip_frame(frames);
  if (steps <= 0) return 0;
  if (steps <= 2) return 0.5 * steps;
  return 1 - smootherstep((steps - 2) / kFrameRate / kEaseBack);
}

// The loop's last frame wraps round to phase 0: it closes on exactly the first pose.
double loop_phase(int i, int frames) { return i == frames - 1 ? 0.0 : double(i) / (frames - 1); }

// The scripted pose at time t (seconds), phase (0..1 over the sequence) and whip weight (jerk).
Eigen::Isometry3d scripted_pose(Preset preset, double t, double phase, double whip) {
  switch (preset) {
    case Preset::kDesk:
      return pose_of(desk_view(t));
    case Preset::kLoop:
      return pose_of(loop_view(phase));
    case Preset::kLowTexture:
      return low_texture_pose(phase);
    case Preset::kLong:
      return long_pose(phase);
    case Preset::kLookalike:
      return lookalike_pose(phase);
    case Preset::kJerk:
      return pose_of(jerk_view(t, whip));
  }
  throw std::logic_error("unknown preset");
}

// Per frame: the loop's phase wraps at the last frame, the others' is i / (frames - 1).
Eigen::Isometry3d scripted_pose(Preset preset, int i, int frames) {
  const double phase = preset == Preset::kLoop ? loop_phase(i, frames) : double(i) / (frames - 1);
  return scripted_pose(preset, i / kFrameRate, phase, whip_weight(i, frames));
}

HandShake make_shake(Preset preset, int frames, uint64_t seed) {
  // The loop's shake repeats over the loop, so that the last pose is the first one.
  const double duration = (frames - 1) / kFrameRate;
  return HandShake(seed, kShakeTranslation, kShakeRotation,
                   preset == Preset::kLoop ? duration : 0.0);
}

}  // namespace

const std::vector<std::string>& preset_names() {
  static const std::vector<std::string> kNames = {"desk",       "loop", "lowtexture",
                                                  "jerk",       "long", "lookalike"};
  return kNames;
}

std::string preset_name(Preset preset) { return preset_names().at(size_t(preset)); }

Preset parse_preset(const std::string& name) {
  const auto& names = preset_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end())
    throw InputError("--preset: unknown preset '" + name +
                     "' (choose desk, loop, lowtexture, jerk, long or lookalike)");
  return Preset(it - names.begin());
}

int jerk_whip_frame(int frames) { return frames / 2 - 1; }

std::string preset_scene(Preset preset) {
  switch (preset) {
    case Preset::kLong:
      return "two_rooms";
    case Preset::kLookalike:
      return "twin_rooms";
    default:
      return "furnished_room";
  }
}

Eigen::Isometry3d look_at(const Vector3d& eye, const Vector3d& target) {
  const Vector3d z = (target - eye).normalized();
  const Vector3d x = z.cross(Vector3d::UnitZ()).normalized();
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  T_w_c.linear() << x, z.cross(x), z;
  T_w_c.translation() = eye;
  return T_w_c;
}

std::vector<Eigen::Isometry3d> make_trajectory(Preset preset, int frames, uint64_t seed) {
  if (frames < 2)
    throw InputError("--frames: need at least 2 frames, got " + std::to_string(frames));
  const double duration = (frames - 1) / kFrameRate;
  const bool loop = preset == Preset::kLoop;
  const HandShake shake = make_shake(preset, frames, seed);
  std::vector<Eigen::Isometry3d> poses;
  for (int i = 0; i < frames; ++i) {
    const double t = loop ? loop_phase(i, frames) * duration : i / kFrameRate;
    poses.push_back(scripted_pose(preset, i, frames) * shake.offset(t));
  }
  return poses;
}

ContinuousTrajectory::ContinuousTrajectory(Preset preset, int frames, uint64_t seed)
    : preset_(preset), frames_(frames), shake_(make_shake(preset, frames, seed)) {
  if (frames < 2)
    throw InputError("--frames: need at least 2 frames, got " + std::to_string(frames));
}

Eigen::Isometry3d ContinuousTrajectory::pose(double t) const {
  const double phase = t / ((frames_ - 1) / kFrameRate);
  return scripted_pose(preset_, t, phase, whip_weight_at(t, frames_)) * shake_.offset(t);
}

}  // namespace slamkit::synth
