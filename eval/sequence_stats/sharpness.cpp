#include "eval/sequence_stats/sharpness.h"

#include <opencv2/imgproc.hpp>

namespace slamkit::stats {

double laplacian_variance(const cv::Mat& image) {
  CV_Assert(image.type() == CV_8UC3 || image.type() == CV_8UC1);
  cv::Mat grey = image;
  if (image.channels() == 3) cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
  cv::Mat laplacian;
  cv::Laplacian(grey, laplacian, CV_64F);
  cv::Scalar mean, stddev;
  cv::meanStdDev(laplacian, mean, stddev);
  return stddev[0] * stddev[0];
}

}  // namespace slamkit::stats
