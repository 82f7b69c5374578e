// The kinect sensor's effects, each measured on rendered frames against the model that made it.
#include "datasets/synth/kinect_sensor.h"

#include <gtest/gtest.h>

#include <cmath>
#include <initializer_list>
#include <map>
#include <opencv2/imgproc.hpp>
#include <set>

#include "core/error.h"
#include "datasets/synth/kinect_renderer.h"
#include "datasets/synth/sensor_streams.h"
#include "synth/shared_room.h"

namespace slamkit::synth {
namespace {

using Eigen::Vector3d;

// Half the synthetic camera's resolution: the tests render many frames.
Camera small_camera() {
  Camera c;
  c.fx = c.fy = 262.5;
  c.cx = 159.5;
  c.cy = 119.5;
  c.width = 320;
  c.height = 240;
  c.depth_scale = 5000.0;
  return c;
}

// Only the effects listed are on.
KinectSettings only(std::initializer_list<KinectEffect> effects) {
  KinectSettings s;
  s.on.assign(s.on.size(), false);
  for (KinectEffect e : effects) s.on[size_t(e)] = true;
  s.holes_per_frame = 0;
  s.dropout_probability = 0;
  return s;
}

// A plain bright room 20 x 20 x 6 m (walls at x, y = +-10), with a plain dark box in it if
// given: scenes whose every depth and colour edge is known.
SyntheticScene plain_room(const std::optional<Eigen::AlignedBox3d>& box) {
  SceneDescription d;
  d.name = "plain_test_room";
  d.room = Eigen::AlignedBox3d(Vector3d(-10, -10, 0), Vector3d(10, 10, 6));
  d.room_styles.fill(TextureStyle::plain_colour({200, 200, 200}));
  if (box) d.furniture.push_back({"box", {{*box, TextureStyle::plain_colour({30, 30, 30})}}});
  d.lights.push_back({Vector3d(0, 0, 5.5)});
  return SyntheticScene(d);
}

// A camera at `eye` looking along world +y (image x along world +x), upright.
Eigen::Isometry3d facing_north(const Vector3d& eye) { return look_at(eye, eye + Vector3d(0, 1, 0)); }

// T0 turned about the camera's y axis (a pan to the right) at `rate` rad/s.
PoseAt panning(const Eigen::Isometry3d& T0, double rate) {
  return [T0, rate](double t) {
    return T0 * Eigen::Isometry3d(Eigen::AngleAxisd(rate * t, Vector3d::UnitY()));
  };
}

cv::Mat grey(const cv::Mat& bgr) {
  cv::Mat g;
  cv::cvtColor(bgr, g, cv::COLOR_BGR2GRAY);
  g.convertTo(g, CV_64F);
  return g;
}

// Mean squared gradient: falls as blur widens the edges.
double sharpness(const cv::Mat& bgr) {
  cv::Mat gx, gy;
  const cv::Mat g = grey(bgr);
  cv::Sobel(g, gx, CV_64F, 1, 0);
  cv::Sobel(g, gy, CV_64F, 0, 1);
  return cv::mean(gx.mul(gx) + gy.mul(gy))[0];
}

// The sub-pixel column where row v crosses from dark (left) to bright, grey level `level`.
double edge_column(const cv::Mat& g, int v, double level) {
  const double* row = g.ptr<double>(v);
  for (int u = 1; u < g.cols; ++u)
    if (row[u - 1] < level && row[u] >= level)
      return u - 1 + (level - row[u - 1]) / (row[u] - row[u - 1]);
  return -1;
}

cv::Mat render_colour(const SyntheticScene& scene, const Camera& camera, const PoseAt& pose_at,
                      const KinectSettings& s, uint64_t frame = 0) {
  return render_kinect_colour(scene, camera, colour_pixel_rays(camera, s), pose_at, s, 1, frame,
                              0.0);
}

TEST(KinectSensor, MotionBlurGrowsWithSpeedAndAStillCameraIsTheUnblurredRender) {
  const SyntheticScene& room = test::shared_room();
  const Camera camera = small_camera();
  const Eigen::Isometry3d T0 = look_at(Vector3d(0.3, -1.2, 1.3), kDeskTopCentre);
  const KinectSettings blur = only({KinectEffect::kMotionBlur});
  double previous = 1e300;
  for (double rate : {0.0, 0.5, 1.0, 2.0, 4.0}) {  // rad/s
    const int subframes = exposure_subframes(room, camera, panning(T0, rate), blur, 0.0);
    // One sub-frame per pixel moved: f * rate * exposure, at least one.
    // One sub-frame per pixel moved: f * rate * exposure at the centre, up to 1.4 times that
    // in the corners; one when still.
    const double centre_px = camera.fx * rate * blur.exposure_s;
    EXPECT_GE(subframes, std::max(1.0, std::ceil(centre_px))) << rate;
    EXPECT_LE(subframes, std::max(1.0, std::ceil(1.4 * centre_px))) << rate;
    const double s = sharpness(render_colour(room, camera, panning(T0, rate), blur));
    EXPECT_LT(s, previous * (rate == 0 ? 1.0 : 0.9)) << rate << " rad/s";
    previous = s;
  }
  // Still: one sub-frame, pixel for pixel the render without blur (noise and all).
  KinectSettings with = KinectSettings(), without = KinectSettings();
  with.on[size_t(KinectEffect::kRollingShutter)] = false;
  without = with;
  without.on[size_t(KinectEffect::kMotionBlur)] = false;
  const PoseAt still = panning(T0, 0.0);
  EXPECT_EQ(exposure_subframes(room, camera, still, with, 0.0), 1);
  const cv::Mat a = render_colour(room, camera, still, with, 5);
  const cv::Mat b = render_colour(room, camera, still, without, 5);
  EXPECT_EQ(cv::norm(a, b, cv::NORM_INF), 0);
}

TEST(KinectSensor, RollingShutterSkewsAVerticalEdgeByReadoutTimesPanRate) {
  // The box's east face ends at x = 0, 1.5 m ahead: a vertical dark-to-bright edge mid-image.
  const SyntheticScene scene = plain_room(Eigen::AlignedBox3d(Vector3d(-5, 3, 0), Vector3d(0, 3.5, 6)));
  const Camera camera = small_camera();
  const Eigen::Isometry3d T0 = facing_north(Vector3d(0, 1.5, 2));
  const double rate = 1.0;  // rad/s, panning right
  const int top = 8, bottom = 232;  // centre rows of the first and last 16-row bands
  for (bool on : {true, false}) {
    const KinectSettings s = on ? only({KinectEffect::kRollingShutter}) : only({});
    const cv::Mat g = grey(render_colour(scene, camera, panning(T0, rate), s));
    double dark = 0, bright = 0;
    for (int v : {top, bottom}) dark += g.at<double>(v, 20) / 2, bright += g.at<double>(v, 300) / 2;
    const double level = (dark + bright) / 2;
    const double skew = edge_column(g, bottom, level) - edge_column(g, top, level);
    // Later rows see the camera turned further right: the edge further left. The edge sits at
    // the image centre, where a turn of a radians moves it f * a pixels.
    const double dt = s.readout_s * (bottom - top) / camera.height;
    const double predicted = on ? -camera.fx * rate * dt : 0.0;
    // Rays go through pixel centres (no antialiasing): an edge is placed to within a pixel.
    EXPECT_NEAR(skew, predicted, 1.0) << (on ? "rolling shutter" : "global shutter");
    if (on) {
      EXPECT_LT(skew, -6.0);
    }
  }
}

TEST(KinectSensor, DepthStampsFollowTheirOwnClockWithTheConfiguredOffsetAndJitter) {
  const KinectSettings s;
  const StreamStamps stamps = make_stream_stamps(s, 3000, 7);
  const double period_us = 1e6 / kFrameRate * (1 + s.depth_drift);
  double sum = 0, sum2 = 0;
  for (int64_t d : stamps.depth) {
    const double since = d - s.depth_offset_s * 1e6;
    const double residual = since - std::round(since / period_us) * period_us;
    sum += residual, sum2 += residual * residual;
  }
  const double n = stamps.depth.size();
  const double mean = sum / n, sigma = std::sqrt(sum2 / n - mean * mean);
  EXPECT_NEAR(mean, 0, 100) << "microseconds";
  EXPECT_NEAR(sigma, s.depth_jitter_s * 1e6, 0.1 * s.depth_jitter_s * 1e6);
  // The drift slips the depth clock by a whole frame every 1 / (30 * drift) s: a recording of
  // 100 s has fewer depth frames than colour ones, as fr1's lists do.
  EXPECT_NEAR(3000 - n, 3000 * s.depth_drift, 2);
  // At the start depth leads colour by the offset.
  EXPECT_NEAR(stamps.depth[0] - stamps.colour[0], s.depth_offset_s * 1e6, 5 * s.depth_jitter_s * 1e6);
  // Pairs are within associate.py's 20 ms, one to one, and most colour frames get one.
  std::set<int> depth_used;
  for (const auto& [c, d] : stamps.pairs) {
    EXPECT_LT(std::llabs(stamps.colour[c] - stamps.depth[d]), 20000);
    EXPECT_TRUE(depth_used.insert(d).second);
  }
  EXPECT_GT(stamps.pairs.size(), 2900u);
  // Groundtruth every 10 ms over both streams.
  EXPECT_EQ(stamps.groundtruth[1] - stamps.groundtruth[0], 10000);
  EXPECT_LE(stamps.groundtruth.front(), std::min(stamps.colour.front(), stamps.depth.front()));
  EXPECT_GE(stamps.groundtruth.back(), std::max(stamps.colour.back(), stamps.depth.back()));
}

TEST(KinectSensor, AssociationTakesTheClosestPairsFirstAsAssociatePyDoes) {
  // Colour 0 is 5 ms from depth 0 and 15 ms from depth 1; colour 1 is 6 ms from depth 0: colour
  // 0 gets depth 0, colour 1 must make do with depth 1 (13 ms) or nothing past 20 ms.
  const std::vector<std::pair<int, int>> pairs =
      associate_stamps({0, 11000, 90000}, {5000, 24000}, 0.02);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0], std::make_pair(0, 0));
  EXPECT_EQ(pairs[1], std::make_pair(1, 1));
}

// Depth (metres) of the valid pixels in the central 100 x 100 window of a wall `z` ahead.
std::vector<double> wall_depths(double z, const KinectSettings& s) {
  static const SyntheticScene room = plain_room(std::nullopt);
  const Camera camera = small_camera();
  const cv::Mat depth = render_kinect_depth(room, camera, facing_north(Vector3d(0, 10 - z, 2)), s,
                                            1, uint64_t(z * 10));
  std::vector<double> out;
  for (int v = 70; v < 170; ++v)
    for (int u = 110; u < 210; ++u)
      if (const uint16_t raw = depth.at<uint16_t>(v, u)) out.push_back(raw / camera.depth_scale);
  return out;
}

TEST(KinectSensor, DepthNoiseOnAFrontoParallelWallMatchesTheAxialModel) {
  const KinectSettings s = only({KinectEffect::kDepthNoise, KinectEffect::kDepthQuantisation});
  for (double z : {1.0, 2.0, 3.0}) {
    const std::vector<double> depths = wall_depths(z, s);
    ASSERT_GT(depths.size(), 9000u) << z;
    double sum = 0, sum2 = 0;
    for (double d : depths) sum += d - z, sum2 += (d - z) * (d - z);
    const double mean = sum / depths.size();
    const double sigma = std::sqrt(sum2 / depths.size() - mean * mean);
    const double model = KinectSettings::axial_sigma(z, 0.0);
    EXPECT_NEAR(sigma, model, 0.2 * model) << "at " << z << " m";
    EXPECT_NEAR(mean, 0, 0.3 * model) << "at " << z << " m";
  }
}

TEST(KinectSensor, DepthOnAPlaneTakesTheDisparityLevelsAtTheirSpacing) {
  const KinectSettings s = only({KinectEffect::kDepthNoise, KinectEffect::kDepthQuantisation});
  const double fb = s.ir_focal_px * s.baseline_m;
  for (double z : {1.0, 2.0, 3.0}) {
    std::map<double, int> counts;
    for (double d : wall_depths(z, s)) ++counts[d];
    ASSERT_GE(counts.size(), 2u) << z;
    double previous = 0;
    for (const auto& [d, count] : counts) {
      // Every value is a disparity level n / 8 px (to the file's 0.2 mm rounding) ...
      const double levels = fb / d / s.disparity_step_px;
      EXPECT_NEAR(fb / (std::round(levels) * s.disparity_step_px), d, 1.1e-4) << z;
      // ... and neighbouring values are neighbouring levels, about z^2 / (8 f b) apart.
      if (previous > 0) {
        const double step = fb / s.disparity_step_px * (1 / std::round(levels) - 1 / (std::round(levels) + 1));
        EXPECT_NEAR(d - previous, step, 2.5e-4) << z;
        EXPECT_NEAR(d - previous, s.depth_step(d), 0.1 * s.depth_step(d)) << z;
      }
      previous = d;
    }
  }
}

TEST(KinectSensor, ABoxBeforeAWallCastsTheProjectorShadowAndFlyingPixelsAtItsEdges) {
  // A box 1.5 m ahead covering x -0.2..0.2, the wall 3 m ahead.
  const SyntheticScene scene =
      plain_room(Eigen::AlignedBox3d(Vector3d(-0.2, 8.5, 0), Vector3d(0.2, 9.0, 6)));
  const Camera camera = small_camera();
  const Eigen::Isometry3d T_w_d = facing_north(Vector3d(0, 7, 2));
  const auto missing_run = [&](const cv::Mat& depth, int v, int from, int step) {
    int run = 0;
    for (int u = from; u >= 0 && u < depth.cols && depth.at<uint16_t>(v, u) == 0; u += step) ++run;
    return run;
  };
  const int v = 120;
  // The box spans u = cx -+ f * 0.2 / 1.5.
  const int left_edge = int(std::floor(camera.cx - camera.fx * 0.2 / 1.5));
  const int right_edge = int(std::ceil(camera.cx + camera.fx * 0.2 / 1.5));
  {
    const KinectSettings s = only({KinectEffect::kProjectorShadow});
    const cv::Mat depth = render_kinect_depth(scene, camera, T_w_d, s, 1, 0);
    // The projector, baseline_m to the right, cannot see the wall just left of the box:
    // f * b * (1 / 1.5 - 1 / 3) pixels of it.
    const double predicted = camera.fx * s.baseline_m * (1 / 1.5 - 1 / 3.0);
    EXPECT_NEAR(missing_run(depth, v, left_edge, -1), predicted, 1.5);
    EXPECT_EQ(missing_run(depth, v, right_edge, 1), 0);
    const cv::Mat lit = render_kinect_depth(scene, camera, T_w_d, only({}), 1, 0);
    EXPECT_EQ(missing_run(lit, v, left_edge, -1), 0);
  }
  // Depth edges: pixels on the box's border go missing or fly between box and wall.
  const auto between = [&](const cv::Mat& depth) {
    int flying = 0, missing = 0;
    for (int row = 20; row < 220; ++row)
      for (int u : {left_edge - 1, left_edge, left_edge + 1, right_edge - 1, right_edge, right_edge + 1}) {
        const double d = depth.at<uint16_t>(row, u) / camera.depth_scale;
        flying += d > 1.6 && d < 2.9;
        missing += d == 0;
      }
    return std::make_pair(flying, missing);
  };
  const auto [flying, missing] =
      between(render_kinect_depth(scene, camera, T_w_d, only({KinectEffect::kDepthEdges}), 1, 0));
  EXPECT_GT(flying, 80);  // of 400 edge pixels, edge_flying = edge_missing = 35 % of them
  EXPECT_GT(missing, 80);
  const auto [flying_off, missing_off] = between(render_kinect_depth(scene, camera, T_w_d, only({}), 1, 0));
  EXPECT_EQ(flying_off, 0);
  EXPECT_EQ(missing_off, 0);
}

TEST(KinectSensor, MisregistrationShiftsDepthAgainstColour) {
  const KinectSettings s = only({KinectEffect::kMisregistration});
  const Eigen::Isometry3d T = facing_north(Vector3d(0, 7, 2));
  const Eigen::Isometry3d offset = T.inverse() * depth_camera_pose(T, s);
  EXPECT_NEAR(offset.translation().x(), s.misregistration_m, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(offset.linear()).angle() * 180 / M_PI, s.misregistration_deg, 1e-9);
  EXPECT_TRUE(depth_camera_pose(T, only({})).isApprox(T));
}

TEST(KinectSensor, ColourNoiseGrowsWithBrightnessAndVignettingDarkensTheCorners) {
  const SyntheticScene room = plain_room(std::nullopt);
  const Camera camera = small_camera();
  const PoseAt wall = panning(facing_north(Vector3d(0, 7, 2)), 0);
  const cv::Mat clean = grey(render_colour(room, camera, wall, only({})));
  const cv::Mat noisy = grey(render_colour(room, camera, wall, only({KinectEffect::kColourNoise})));
  cv::Scalar mean, sigma;
  cv::meanStdDev(noisy(cv::Rect(110, 70, 100, 100)) - clean(cv::Rect(110, 70, 100, 100)), mean, sigma);
  // Grey mixes the channels' independent noise: its variance is sum(w_c^2) times a channel's.
  const KinectSettings s;
  const double level = cv::mean(clean(cv::Rect(110, 70, 100, 100)))[0];
  ASSERT_LT(level, 230);  // no clipping at 255
  const double weights2 = 0.299 * 0.299 + 0.587 * 0.587 + 0.114 * 0.114;
  const double predicted = std::sqrt(weights2 * (s.read_noise * s.read_noise + s.shot_gain * level));
  EXPECT_NEAR(sigma[0], predicted, 0.2 * predicted);
  const cv::Mat vignetted = grey(render_colour(room, camera, wall, only({KinectEffect::kVignetting})));
  const double centre = vignetted.at<double>(120, 160) / clean.at<double>(120, 160);
  const double corner = vignetted.at<double>(0, 0) / clean.at<double>(0, 0);
  EXPECT_NEAR(centre, 1.0, 0.01);
  EXPECT_NEAR(corner, 1 - s.vignetting, 0.02);
}

TEST(KinectSensor, AutoExposureDriftsSmoothlyAndDisparityQuantisationGrowsWithZSquared) {
  const KinectSettings s;
  EXPECT_DOUBLE_EQ(exposure_gain(s, 1, 0.0), 1.0);
  double lo = 1, hi = 1;
  for (double t = 0; t < 60; t += 1 / kFrameRate) {
    const double g = exposure_gain(s, 1, t);
    lo = std::min(lo, g), hi = std::max(hi, g);
    EXPECT_LT(std::abs(std::log(exposure_gain(s, 1, t + 1 / kFrameRate) / g)), 0.01);
  }
  EXPECT_GT(hi / lo, 1.2);
  EXPECT_NEAR(s.depth_step(2.0) / s.depth_step(1.0), 4.0, 1e-12);
  EXPECT_NEAR(s.depth_step(1.0), 0.125 / (580 * 0.075), 1e-12);
}

TEST(KinectSensor, LensDistortionRaysLandOnTheirPixelsThroughTheCalibrationsDistortion) {
  KinectSettings s = only({KinectEffect::kLensDistortion});
  const Camera camera = small_camera();
  const Camera distorted = kinect_colour_camera(camera, s);
  EXPECT_DOUBLE_EQ(distorted.distortion.k1, s.k1);
  const std::vector<Eigen::Vector3d> rays = colour_pixel_rays(camera, s);
  // The reader undistorts with calibration.yaml's distortion: projecting each pixel's ray
  // through it must give the pixel back; towards the corners the rays bend away from pinhole.
  double max_bend = 0;
  for (int v = 0; v < camera.height; v += 17)
    for (int u = 0; u < camera.width; u += 17) {
      const Eigen::Vector3d& ray = rays[size_t(v) * camera.width + u];
      EXPECT_LT((distorted.project_distorted(ray) - Eigen::Vector2d(u, v)).norm(), 0.01) << u << "," << v;
      max_bend = std::max(max_bend, (camera.project(ray) - Eigen::Vector2d(u, v)).norm());
    }
  EXPECT_GT(max_bend, 3.0);
  // Off: pinhole rays and no distortion in the calibration.
  s.on[size_t(KinectEffect::kLensDistortion)] = false;
  EXPECT_TRUE(kinect_colour_camera(camera, s).distortion.is_zero());
  EXPECT_NEAR(colour_pixel_rays(camera, s)[0].x(), -camera.cx / camera.fx, 1e-15);
}

TEST(KinectSensor, EffectsSwitchByNameAndUnknownNamesAreInputErrors) {
  KinectSettings s;
  EXPECT_FALSE(s.has(KinectEffect::kLensDistortion));
  switch_effects(s, "motion_blur,rolling_shutter", false, "--sensor-off");
  EXPECT_FALSE(s.has(KinectEffect::kMotionBlur));
  EXPECT_FALSE(s.has(KinectEffect::kRollingShutter));
  EXPECT_TRUE(s.has(KinectEffect::kDepthNoise));
  switch_effects(s, "lens_distortion", true, "--sensor-on");
  EXPECT_TRUE(s.has(KinectEffect::kLensDistortion));
  EXPECT_THROW(switch_effects(s, "motion_blurr", false, "--sensor-off"), InputError);
}

}  // namespace
}  // namespace slamkit::synth
