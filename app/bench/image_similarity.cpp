#include "app/bench/image_similarity.hpp"

#include <array>
#include <cmath>

namespace ecoview {
namespace {

constexpr int window_radius = 5;  // 11 × 11
constexpr double window_sigma = 1.5;
constexpr double c1 = (0.01 * 255.0) * (0.01 * 255.0), c2 = (0.03 * 255.0) * (0.03 * 255.0);

std::vector<double> luminance(const Image8& image) {
  std::vector<double> y(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  for (std::size_t i = 0; i < y.size(); ++i) {
    const std::uint8_t* rgb = &image.samples[3 * i];
    y[i] = 0.299 * rgb[0] + 0.587 * rgb[1] + 0.114 * rgb[2];
  }
  return y;
}

// The Gaussian-weighted mean of `values` around every pixel, the window cut at the edges and its
// weights scaled to sum to 1 there: a row pass, then a column pass (the window is separable).
std::vector<double> window_means(const std::vector<double>& values, int width, int height) {
  std::array<double, 2 * window_radius + 1> weights{};
  for (int d = -window_radius; d <= window_radius; ++d) weights[d + window_radius] = std::exp(-0.5 * d * d / (window_sigma * window_sigma));
  auto pass = [&](const std::vector<double>& in, int step, int count, int lines, int line_step) {
    std::vector<double> out(in.size());
    for (int line = 0; line < lines; ++line) {
      for (int i = 0; i < count; ++i) {
        double sum = 0.0, weight = 0.0;
        for (int d = std::max(-window_radius, -i); d <= std::min(window_radius, count - 1 - i); ++d) {
          const double w = weights[d + window_radius];
          sum += w * in[static_cast<std::size_t>(line * line_step + (i + d) * step)];
          weight += w;
        }
        out[static_cast<std::size_t>(line * line_step + i * step)] = sum / weight;
      }
    }
    return out;
  };
  return pass(pass(values, 1, width, height, width), width, height, width, 1);
}

double to_linear(double srgb) { return srgb <= 0.04045 ? srgb / 12.92 : std::pow((srgb + 0.055) / 1.055, 2.4); }
double to_srgb(double linear) { return linear <= 0.0031308 ? 12.92 * linear : 1.055 * std::pow(linear, 1.0 / 2.4) - 0.055; }

}  // namespace

double psnr_over(const std::vector<bool>& pixels, const Image8& reference, const Image8& image) {
  double squared_error = 0.0;
  std::size_t samples = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (!pixels[i]) continue;
    for (std::size_t c = 3 * i; c < 3 * i + 3; ++c) {
      const double e = static_cast<double>(reference.samples[c]) - static_cast<double>(image.samples[c]);
      squared_error += e * e;
    }
    samples += 3;
  }
  if (samples == 0) return 0.0;
  return squared_error > 0.0 ? 10.0 * std::log10(255.0 * 255.0 * static_cast<double>(samples) / squared_error) : 99.0;
}

double ssim_over(const std::vector<bool>& pixels, const Image8& reference, const Image8& image) {
  const int w = image.width, h = image.height;
  const std::vector<double> x = luminance(reference), y = luminance(image);
  std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    xx[i] = x[i] * x[i];
    yy[i] = y[i] * y[i];
    xy[i] = x[i] * y[i];
  }
  const std::vector<double> mx = window_means(x, w, h), my = window_means(y, w, h), mxx = window_means(xx, w, h),
                            myy = window_means(yy, w, h), mxy = window_means(xy, w, h);
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    if (!pixels[i]) continue;
    const double vx = mxx[i] - mx[i] * mx[i], vy = myy[i] - my[i] * my[i], cov = mxy[i] - mx[i] * my[i];
    sum += (2.0 * mx[i] * my[i] + c1) * (2.0 * cov + c2) / ((mx[i] * mx[i] + my[i] * my[i] + c1) * (vx + vy + c2));
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

Image8 box_filtered(const Image8& image, int factor) {
  std::array<double, 256> linear{};
  for (int v = 0; v < 256; ++v) linear[static_cast<std::size_t>(v)] = to_linear(v / 255.0);
  Image8 out{image.width / factor, image.height / factor, 3, {}};
  out.samples.resize(static_cast<std::size_t>(out.width) * static_cast<std::size_t>(out.height) * 3);
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int sy = 0; sy < factor; ++sy) {
          for (int sx = 0; sx < factor; ++sx) sum += linear[image.at(factor * x + sx, factor * y + sy, c)];
        }
        const double srgb = to_srgb(sum / (factor * factor));
        out.samples[(static_cast<std::size_t>(y) * static_cast<std::size_t>(out.width) + static_cast<std::size_t>(x)) * 3 +
                    static_cast<std::size_t>(c)] = static_cast<std::uint8_t>(std::lround(255.0 * srgb));
      }
    }
  }
  return out;
}

}  // namespace ecoview
