#pragma once
// The `kinect` sensor of `slamkit synth --sensor kinect`: what a Kinect v1 does to the frames
// beyond the ideal sensor (sensor_model.h): motion blur, rolling shutter, separate colour and
// depth streams, a camera response with shot and read noise, auto-exposure and vignetting,
// structured-light depth (disparity quantisation, axial and lateral noise, projector shadow,
// flying pixels) and a colour-depth misregistration. Every effect is a switch and every number a
// field with its source; docs/sensor.md explains them. Written by hand: it is the model under
// test, and no library models a Kinect.
#include <cstdint>
#include <string>
#include <vector>

#include "datasets/synth/counter_rng.h"

namespace YAML {
class Emitter;
class Node;
}  // namespace YAML

namespace slamkit::synth {

// The effects, each on or off; names as `--sensor-off` and synthetic.yaml spell them.
enum class KinectEffect {
  kMotionBlur,       // motion_blur
  kRollingShutter,   // rolling_shutter
  kStreamTiming,     // stream_timing: depth stamps of their own, 100 Hz groundtruth
  kColourNoise,      // colour_noise: shot and read noise
  kAutoExposure,     // auto_exposure
  kVignetting,       // vignetting
  kLensDistortion,   // lens_distortion (off by default)
  kDepthQuantisation,  // depth_quantisation
  kDepthNoise,       // depth_noise: axial and lateral
  kDepthEdges,       // depth_edges: flying and missing pixels at depth discontinuities
  kProjectorShadow,  // projector_shadow
  kMisregistration,  // misregistration
  kCount
};

const std::vector<std::string>& kinect_effect_names();

struct KinectSettings {
  // Which effects are on, indexed by KinectEffect: all but lens_distortion by default.
  std::vector<bool> on = default_effects();
  static std::vector<bool> default_effects();

  // Timing of the colour camera (MT9M112 sensor at 30 Hz).
  double exposure_s = 0.015;  // assumed indoor auto-exposure (at most a frame, 33 ms, at 30 Hz)
  double readout_s = 0.030;   // assumed rolling readout of the 480 rows, near a frame period
  double blur_step_px = 1.0;  // a sub-frame per this many pixels moved during the exposure
  int max_subframes = 24;     // cap for the whip of `jerk` (about 20 deg in a frame)

  // Depth stream against the colour one (measured on TUM fr1/desk's full lists, docs/sensor.md).
  double depth_offset_s = -0.014;      // depth minus colour stamp at the start (fr1: -16..+18 ms)
  double depth_drift = 0.0008;         // depth clock runs slow by this ratio (fr1: ~0.8 ms/s)
  double depth_jitter_s = 0.002;       // per-stamp jitter (fr1: 2.9 ms per consecutive step)
  double groundtruth_rate_hz = 100.0;  // TUM's motion capture rate

  // Colour response (in 8-bit grey levels of the output).
  double read_noise = 1.5;       // grey levels; assumed, typical of small CMOS sensors
  double shot_gain = 0.12;       // grey levels per electron (variance = shot_gain * level); assumed
  double exposure_drift = 0.15;  // auto-exposure gain's log wanders this much over ~10 s; assumed
  double vignetting = 0.25;      // share of brightness lost at the image corners; assumed
  // fr1's RGB distortion (TUM's calibration page: k1 k2 p1 p2 k3).
  double k1 = 0.2624, k2 = -0.9531, p1 = -0.0054, p2 = 0.0026, k3 = 1.1633;

  // Structured-light depth (Khoshelham and Elberink 2012; Kinect v1).
  double baseline_m = 0.075;          // IR camera to projector along x
  double ir_focal_px = 580.0;         // IR camera focal length
  double disparity_step_px = 0.125;   // disparity is reported in 1/8 pixel
  double min_range_m = 0.5;           // operating range 0.5 .. 5 m (Khoshelham and Elberink 2012)
  double max_range_m = 5.0;
  double max_incidence_deg = 78.0;    // no return beyond (Nguyen et al. 2012's data ends there)
  double dropout_probability = 0.002;  // isolated missing pixels, as the ideal sensor
  int holes_per_frame = 4;             // small discs of missing depth, as the ideal sensor
  double edge_jump = 0.04;            // a neighbour this much farther (relative) makes an edge
  double edge_flying = 0.35;          // chance an edge pixel takes a mixed (flying) depth
  double edge_missing = 0.35;         // chance an edge pixel returns nothing
  // Colour camera against depth camera: a residual of the factory registration.
  double misregistration_m = 0.004;   // along x; assumed (about 2 px of edge offset at 1 m)
  double misregistration_deg = 0.25;  // about y; assumed

  bool has(KinectEffect e) const { return on[size_t(e)]; }

  // Axial depth noise sigma (metres) at depth z and incidence angle theta (radians), Nguyen,
  // Izadi and Lovell 2012, eq. 6: it includes the disparity quantisation's share.
  static double axial_sigma(double z, double theta);
  // Lateral noise sigma (pixels) at incidence theta, Nguyen et al. 2012 eq. 5.
  static double lateral_sigma_px(double theta);
  // The depth step between neighbouring disparity levels at z: z^2 * step / (f * b).
  double depth_step(double z) const;
  // z after the disparity is rounded to disparity_step_px.
  double quantise_depth(double z) const;
};

// Throws InputError naming the first setting out of its range (times, rates, probabilities).
void check_kinect_settings(const KinectSettings& settings);

// Turns effects off by a comma-separated list of names ("motion_blur,rolling_shutter"), or on
// with `on_list`. Throws InputError naming `option` and listing the valid names.
void switch_effects(KinectSettings& settings, const std::string& list, bool on,
                    const std::string& option);

// The settings as a YAML map (synthetic.yaml's `kinect:`): `effects: {name: on/off}` and every
// number by its field name.
void emit_kinect_settings(YAML::Emitter& out, const KinectSettings& settings);
// Reads that map back; keys left out keep their defaults. Throws InputError naming `file` for an
// unknown key or a value of the wrong type.
KinectSettings read_kinect_settings(const YAML::Node& node, const std::string& file);

}  // namespace slamkit::synth
