#pragma once
// Camera paths through the synthetic scenes (room_layout.h, multi_room_layouts.h), one per
// test scenario. Poses are
// T_w_c with the camera looking along +z, x right, y down (TUM / OpenCV); world z is up.
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

#include "datasets/synth/hand_shake.h"

namespace slamkit::synth {

enum class Preset {
  kDesk,        // hand-held sweeps around the desk, like TUM fr1/desk
  kLoop,        // once around the desk looking out at the walls, ending exactly on the first pose
  kLowTexture,  // textured views, several seconds facing the plain wall up close, textured
  kJerk,        // smooth panning with one two-frame whip (about 20 deg and 15 cm per frame)
  kLong,        // through two rooms and back to the start (two_rooms; 2,000 frames or more)
  kLookalike,   // a place, its look-alike twin 5.1 m away, then the place again (twin_rooms)
};

constexpr double kFrameRate = 30.0;

// "desk", "loop", "lowtexture", "jerk", "long", "lookalike"
const std::vector<std::string>& preset_names();
std::string preset_name(Preset preset);
// Throws InputError listing the valid names.
Preset parse_preset(const std::string& name);

// The scene a preset films, by name (make_named_scene): furnished_room, two_rooms or
// twin_rooms.
std::string preset_scene(Preset preset);

// Poses of frames 0..frames-1 at kFrameRate. `desk` and `jerk` move at fixed speeds (so a
// longer sequence covers more of the same motion); the others stretch their script over the
// frames. The seed drives the hand shake. Throws InputError if frames < 2.
std::vector<Eigen::Isometry3d> make_trajectory(Preset preset, int frames, uint64_t seed);

// The same path at any time t (seconds; frame i is at i / kFrameRate), for sensors that sample
// between frames (rolling shutter, exposure, a depth stream of its own). At frame times it
// agrees with make_trajectory to rounding; the loop and the scripted presets run on past the
// last frame time (phases above 1 hold the last key, the loop goes round again).
class ContinuousTrajectory {
 public:
  // Throws InputError if frames < 2.
  ContinuousTrajectory(Preset preset, int frames, uint64_t seed);
  Eigen::Isometry3d pose(double t) const;

 private:
  Preset preset_;
  int frames_;
  HandShake shake_;
};

// Camera at `eye` looking at `target`, its image upright in a z-up world.
Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

// The frame of the `jerk` whip: the big steps are frames whip..whip+1 and whip+1..whip+2.
int jerk_whip_frame(int frames);

}  // namespace slamkit::synth
