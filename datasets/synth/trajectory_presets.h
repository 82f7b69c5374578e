#pragma once
// Camera paths through the furnished room (room_layout.h), one per test scenario. Poses are
// T_w_c with the camera looking along +z, x right, y down (TUM / OpenCV); world z is up.
#include <Eigen/Geometry>
#include <cstdint>
#include <string>
#include <vector>

namespace slamkit::synth {

enum class Preset {
  kDesk,        // hand-held sweeps around the desk, like TUM fr1/desk
  kLoop,        // once around the desk, ending exactly on the first pose
  kLowTexture,  // textured views, several seconds facing the plain wall up close, textured
  kJerk,        // smooth panning with one two-frame whip (about 20 deg and 15 cm per frame)
};

constexpr double kFrameRate = 30.0;

const std::vector<std::string>& preset_names();  // "desk", "loop", "lowtexture", "jerk"
std::string preset_name(Preset preset);
// Throws InputError listing the valid names.
Preset parse_preset(const std::string& name);

// Poses of frames 0..frames-1 at kFrameRate. `desk` and `jerk` move at fixed speeds (so a
// longer sequence covers more of the same motion); `loop` and `lowtexture` stretch their
// script over the frames. The seed drives the hand shake. Throws InputError if frames < 2.
std::vector<Eigen::Isometry3d> make_trajectory(Preset preset, int frames, uint64_t seed);

// Camera at `eye` looking at `target`, its image upright in a z-up world.
Eigen::Isometry3d look_at(const Eigen::Vector3d& eye, const Eigen::Vector3d& target);

// The frame of the `jerk` whip: the big steps are frames whip..whip+1 and whip+1..whip+2.
int jerk_whip_frame(int frames);

}  // namespace slamkit::synth
