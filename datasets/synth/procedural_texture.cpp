#include "datasets/synth/procedural_texture.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <string>
#include <vector>

#include "datasets/synth/counter_rng.h"

namespace slamkit::synth {
namespace {

// Random values on a grid `wavelength_m` apart, interpolated bicubically: smooth noise at
// one scale, in [-1, 1] (roughly).
cv::Mat value_noise(cv::Size size, double texels_per_metre, double wavelength_m, CounterRng& rng) {
  const double cell = wavelength_m * texels_per_metre;
  cv::Mat grid(std::max(2, int(std::ceil(size.height / cell)) + 1),
               std::max(2, int(std::ceil(size.width / cell)) + 1), CV_32F);
  for (int r = 0; r < grid.rows; ++r)
    for (int c = 0; c < grid.cols; ++c) grid.at<float>(r, c) = float(rng.uniform(-1, 1));
  cv::Mat out;
  cv::resize(grid, out, size, 0, 0, cv::INTER_CUBIC);
  return out;
}

cv::Scalar scaled(const cv::Scalar& c, double s) {
  return {std::min(255.0, c[0] * s), std::min(255.0, c[1] * s), std::min(255.0, c[2] * s)};
}

cv::Scalar pick_colour(const TextureStyle& style, CounterRng& rng) {
  switch (int(rng.uniform() * 7)) {
    case 0:
      return scaled(style.base, 0.45);
    case 1:
      return scaled(style.base, 1.35);
    case 2:
      return style.accent;
    case 3:
      return scaled(style.accent, 0.55);
    case 4:
      return {25, 25, 30};
    case 5:
      return {235, 235, 230};
    default:
      return {rng.uniform(20, 235), rng.uniform(20, 235), rng.uniform(20, 235)};
  }
}

std::vector<cv::Point> rotated_rect(cv::Point2d centre, double w, double h, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  std::vector<cv::Point> pts;
  const std::pair<double, double> corners[] = {{-w, -h}, {w, -h}, {w, h}, {-w, h}};
  for (auto [x, y] : corners)
    pts.emplace_back(int(std::lround(centre.x + 0.5 * (c * x - s * y))),
                     int(std::lround(centre.y + 0.5 * (s * x + c * y))));
  return pts;
}

// One random sharp-edged mark; sizes are drawn in metres so density does not depend on the
// texture resolution.
void draw_mark(cv::Mat& img, double tpm, const TextureStyle& style, CounterRng& rng) {
  const cv::Point2d at(rng.uniform(0, img.cols), rng.uniform(0, img.rows));
  const auto px = [tpm](double metres) { return metres * tpm; };
  const cv::Scalar colour = pick_colour(style, rng);
  const int thickness = 1 + int(rng.uniform() * 3);
  switch (int(rng.uniform() * 8)) {
    case 0: {  // blob
      const cv::Size axes(int(px(rng.uniform(0.006, 0.05))), int(px(rng.uniform(0.006, 0.05))));
      cv::ellipse(img, at, axes, rng.uniform(0, 180), 0, 360, colour, cv::FILLED, cv::LINE_AA);
      break;
    }
    case 1: {  // filled rotated rectangle
      const auto pts = rotated_rect(at, px(rng.uniform(0.02, 0.14)), px(rng.uniform(0.02, 0.14)),
                                    rng.uniform(0, M_PI));
      cv::fillConvexPoly(img, pts, colour, cv::LINE_AA);
      break;
    }
    case 2: {  // rectangle outline
      const cv::Point2d size(px(rng.uniform(0.03, 0.2)), px(rng.uniform(0.03, 0.2)));
      cv::rectangle(img, at, at + size, colour, thickness, cv::LINE_AA);
      break;
    }
    case 3: {  // line segment
      const double a = rng.uniform(0, 2 * M_PI), len = px(rng.uniform(0.04, 0.3));
      cv::line(img, at, at + cv::Point2d(len * std::cos(a), len * std::sin(a)), colour, thickness,
               cv::LINE_AA);
      break;
    }
    case 4: {  // checker patch
      const int n = 3 + int(rng.uniform() * 4);
      const double cell = px(rng.uniform(0.008, 0.03));
      const cv::Scalar other = pick_colour(style, rng);
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
          cv::rectangle(img, at + cv::Point2d(i * cell, j * cell),
                        at + cv::Point2d((i + 1) * cell, (j + 1) * cell),
                        (i + j) % 2 ? colour : other, cv::FILLED);
      break;
    }
    case 5: {  // stripes patch
      const int n = 3 + int(rng.uniform() * 6);
      const double width = px(rng.uniform(0.006, 0.02)), length = px(rng.uniform(0.04, 0.15));
      const bool vertical = rng.uniform() < 0.5;
      const cv::Scalar other = pick_colour(style, rng);
      for (int i = 0; i < n; ++i) {
        const cv::Point2d step = vertical ? cv::Point2d(i * width, 0) : cv::Point2d(0, i * width);
        const cv::Point2d extent =
            vertical ? cv::Point2d(width, length) : cv::Point2d(length, width);
        cv::rectangle(img, at + step, at + step + extent, i % 2 ? colour : other, cv::FILLED);
      }
      break;
    }
    case 6: {  // a few letters and digits: many corners per square centimetre
      static const char kChars[] = "ABCDEFGHKLMNPRSTUVWXYZ0123456789#";
      std::string text;
      for (int i = 2 + int(rng.uniform() * 5); i > 0; --i)
        text += kChars[int(rng.uniform() * (sizeof kChars - 1))];
      const double scale = px(rng.uniform(0.015, 0.05)) / 22.0;  // Hershey simplex: ~22 px
      cv::putText(img, text, at, cv::FONT_HERSHEY_SIMPLEX, scale, colour,
                  std::max(1, int(scale * 2)), cv::LINE_AA);
      break;
    }
    default: {  // triangle
      std::vector<cv::Point> pts;
      for (int i = 0; i < 3; ++i)
        pts.emplace_back(at +
                         cv::Point2d(px(rng.uniform(-0.06, 0.06)), px(rng.uniform(-0.06, 0.06))));
      cv::fillConvexPoly(img, pts, colour, cv::LINE_AA);
    }
  }
}

// Tiles of slightly different shades separated by dark joints: corners on a regular grid.
void draw_tiles(cv::Mat& img, double tpm, double tile_m, CounterRng& rng) {
  const double tile = tile_m * tpm;
  for (double y = 0; y < img.rows; y += tile)
    for (double x = 0; x < img.cols; x += tile) {
      const cv::Rect cell(int(x), int(y), int(std::ceil(tile)), int(std::ceil(tile)));
      cv::Mat roi = img(cell & cv::Rect(0, 0, img.cols, img.rows));
      roi.convertTo(roi, -1, rng.uniform(0.8, 1.15));
      cv::rectangle(img, cell, cv::Scalar(35, 40, 45), std::max(1, int(0.006 * tpm)));
    }
}

}  // namespace

cv::Mat make_procedural_image(double width_m, double height_m, double texels_per_metre,
                              const TextureStyle& style, uint64_t seed) {
  const cv::Size size(std::max(8, int(std::lround(width_m * texels_per_metre))),
                      std::max(8, int(std::lround(height_m * texels_per_metre))));
  if (style.plain) return cv::Mat(size, CV_8UC3, style.base);

  CounterRng rng(seed, kStreamTexture, 0);
  // Brightness from four octaves (metres, grey levels), a large-scale tint towards the accent.
  cv::Mat shade(size, CV_32F, cv::Scalar(0));
  const std::pair<double, double> octaves[] = {
      {0.6, 22.0}, {0.2, 16.0}, {0.07, 12.0}, {0.025, 8.0}};
  for (auto [wavelength, amplitude] : octaves)
    shade += amplitude * value_noise(size, texels_per_metre, wavelength, rng);
  cv::Mat tint = value_noise(size, texels_per_metre, 0.4, rng) * 0.5 + 0.5;
  std::vector<cv::Mat> channels(3);
  for (int c = 0; c < 3; ++c)
    channels[c] = style.base[c] + tint.mul(0.6 * (style.accent[c] - style.base[c])) + shade;
  cv::Mat image;
  cv::merge(channels, image);
  image.convertTo(image, CV_8UC3);

  if (style.tile_size_m > 0) draw_tiles(image, texels_per_metre, style.tile_size_m, rng);
  const int marks = int(std::ceil(width_m * height_m * 70.0));
  for (int i = 0; i < marks; ++i) draw_mark(image, texels_per_metre, style, rng);

  // Fine grain over everything, so that the flat marks are not perfectly flat either.
  cv::Mat grain = value_noise(size, texels_per_metre, 0.008, rng) * 6.0;
  cv::Mat grain3;
  cv::merge(std::vector<cv::Mat>{grain, grain, grain}, grain3);
  cv::Mat result;
  image.convertTo(result, CV_32FC3);
  result += grain3;
  result.convertTo(result, CV_8UC3);
  return result;
}

}  // namespace slamkit::synth
