// --render FILE.png: a picture of the input beside the result, without a
// display. Both are seen along the input's axis of least extent
// (orthographic), every point a small disc coloured by its importance, the
// nearer hiding the farther; the discs have the same size in both panels, so
// that the result shows how sparse it is where. PNG through Debian's libstb
// (stb_image_write), the labels with stb_easy_font.

#ifndef ENTROPY_SIMPLIFY_RENDER_PNG_H
#define ENTROPY_SIMPLIFY_RENDER_PNG_H

#include "byte_io.h"
#include "point_files.h"

#include <stb_easy_font.h>
#include <stb_image_write.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <string>
#include <vector>

namespace entropy_simplify {

struct Picture
{
  int width = 0, height = 0;
  std::vector<std::uint8_t> rgb; // row by row, from the top
  std::vector<float> depth;      // toward the viewer; -infinity where nothing is drawn

  Picture(int w, int h)
    : width(w), height(h), rgb(std::size_t(w) * std::size_t(h) * 3, 255),
      depth(std::size_t(w) * std::size_t(h), -std::numeric_limits<float>::infinity())
  {}

  void fill(int x, int y, const std::array<std::uint8_t, 3>& colour)
  {
    if (x < 0 || y < 0 || x >= width || y >= height)
      return;
    std::copy(colour.begin(), colour.end(), rgb.begin() + (std::ptrdiff_t(y) * width + x) * 3);
  }
};

namespace render_detail {

constexpr int panel = 640, margin = 24, title = 40, legend = 28, text_scale = 2;

// Viridis, from dark purple (0) to yellow (1), by linear steps.
inline std::array<std::uint8_t, 3> colour_of(double t)
{
  static const double stops[5][3] = {
    { 68, 1, 84 }, { 59, 82, 139 }, { 33, 145, 140 }, { 94, 201, 98 }, { 253, 231, 37 }
  };
  const double s = (std::min)(1., (std::max)(0., t)) * 4.;
  const int i = (std::min)(3, int(s));
  std::array<std::uint8_t, 3> c;
  for (int k = 0; k < 3; ++k)
    c[k] = std::uint8_t(std::lround(stops[i][k] + (s - i) * (stops[i + 1][k] - stops[i][k])));
  return c;
}

// The view: the centroid and the principal axes of the input, the least
// extended last, so that (u, v) along the first two fill the panel.
struct View
{
  Eigen::Vector3d centre;
  Eigen::Matrix3d axes; // columns: u, v, toward the viewer
  double scale;         // pixels per unit
};

inline View view_of(const std::vector<Eigen::Vector3d>& points)
{
  View view;
  view.centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& p : points)
    view.centre += p;
  view.centre /= double(points.size());
  // the offsets in units of the largest, so that their squares neither
  // overflow nor underflow at any scale the package accepts (up to 1e150)
  double unit = 0.;
  for (const Eigen::Vector3d& p : points)
    unit = (std::max)(unit, (p - view.centre).cwiseAbs().maxCoeff());
  if (!(unit > 0.))
    unit = 1.;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  for (const Eigen::Vector3d& p : points)
    covariance += ((p - view.centre) / unit) * ((p - view.centre) / unit).transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(covariance); // eigenvalues ascending
  view.axes << solver.eigenvectors().col(2), solver.eigenvectors().col(1), solver.eigenvectors().col(0);
  double extent = 0.;
  for (const Eigen::Vector3d& p : points)
  {
    const Eigen::Vector3d q = view.axes.transpose() * (p - view.centre);
    extent = (std::max)({ extent, std::abs(q.x()), std::abs(q.y()) });
  }
  view.scale = extent > 0. ? 0.48 * panel / extent : 1.;
  return view;
}

// A disc of `radius` pixels at the point, in the panel whose left edge is
// at `left`, where it is nearer than what is drawn there. Its depth is in
// pixels, as its position: in the cloud's units, a float would overflow
// beyond 3.4e38 and lose the order of depths near 1e-45.
inline void splat(Picture& picture, const View& view, int left, const Eigen::Vector3d& p, double radius,
                  const std::array<std::uint8_t, 3>& colour)
{
  const Eigen::Vector3d q = view.axes.transpose() * (p - view.centre) * view.scale;
  const double cx = left + margin + panel / 2. + q.x();
  const double cy = title + margin + panel / 2. - q.y();
  const int reach = int(std::ceil(radius));
  for (int y = int(std::floor(cy)) - reach; y <= int(std::floor(cy)) + reach; ++y)
    for (int x = int(std::floor(cx)) - reach; x <= int(std::floor(cx)) + reach; ++x)
    {
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (x < 0 || y < 0 || x >= picture.width || y >= picture.height || dx * dx + dy * dy > radius * radius + 0.5)
        continue;
      float& depth = picture.depth[std::size_t(y) * std::size_t(picture.width) + std::size_t(x)];
      if (float(q.z()) > depth)
      {
        depth = float(q.z());
        picture.fill(x, y, colour);
      }
    }
}

// `text` at (x, y), its letters scaled up, in dark grey.
inline void label(Picture& picture, int x, int y, std::string text)
{
  std::vector<char> quads(text.size() * 400 + 1000);
  const int count = stb_easy_font_print(0.f, 0.f, text.data(), nullptr, quads.data(), int(quads.size()));
  for (int q = 0; q < count; ++q)
  {
    const float* corner = reinterpret_cast<const float*>(quads.data() + q * 64); // 4 vertices of 16 bytes
    const float x0 = corner[0], y0 = corner[1], x1 = corner[8], y1 = corner[9];
    for (int py = int(y0 * text_scale); py < int(y1 * text_scale); ++py)
      for (int px = int(x0 * text_scale); px < int(x1 * text_scale); ++px)
        picture.fill(x + px, y + py, { 40, 40, 40 });
  }
}

} // namespace render_detail

// The input (left) beside the kept rows (right), coloured by `importance`
// (one per row) over its greatest value.
inline Picture render_side_by_side(const Cloud& cloud, const std::vector<std::size_t>& kept,
                                   const std::vector<double>& importance)
{
  namespace r = render_detail;
  const Column* xyz[3] = { cloud.table.find("x"), cloud.table.find("y"), cloud.table.find("z") };
  std::vector<Eigen::Vector3d> points(cloud.size());
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    const std::array<double, 3> p = coordinates(cloud, xyz, i);
    points[i] = Eigen::Vector3d(p[0], p[1], p[2]);
  }
  const r::View view = r::view_of(points);
  const double highest = *std::max_element(importance.begin(), importance.end());
  const auto colour = [&](std::size_t i) { return r::colour_of(highest > 0. ? importance[i] / highest : 0.); };
  // discs that about cover the input's panel, the same in the result's
  const double radius = std::clamp(0.6 * r::panel / std::sqrt(double(points.size())), 0.5, 4.);

  const int width = 2 * (r::panel + 2 * r::margin);
  Picture picture(width, r::title + r::panel + 2 * r::margin + r::legend);
  for (std::size_t i = 0; i < points.size(); ++i)
    r::splat(picture, view, 0, points[i], radius, colour(i));
  for (std::size_t i : kept)
    r::splat(picture, view, width / 2, points[i], radius, colour(i));
  r::label(picture, r::margin, 10, "input: " + std::to_string(points.size()) + " points");
  r::label(picture, width / 2 + r::margin, 10, "result: " + std::to_string(kept.size()) + " points");
  const int bar_y = r::title + r::panel + 2 * r::margin;
  for (int x = 0; x < 200; ++x)
    for (int y = 0; y < 12; ++y)
      picture.fill(r::margin + x, bar_y + y, r::colour_of(x / 199.));
  r::label(picture, r::margin + 212, bar_y - 1, "importance, 0 to " + std::to_string(highest).substr(0, 6));
  return picture;
}

// The picture as a PNG file, encoded in memory: no exception may cross
// stb's C code, so that the sink's errors come after it.
inline void write_png(Sink& out, const Picture& picture)
{
  struct Encoded
  {
    std::string bytes;
    bool complete = true;
  } encoded;
  const auto append = [](void* context, void* data, int size) {
    Encoded& e = *static_cast<Encoded*>(context);
    try
    {
      e.bytes.append(static_cast<const char*>(data), std::size_t(size));
    }
    catch (const std::bad_alloc&)
    {
      e.complete = false;
    }
  };
  if (!stbi_write_png_to_func(append, &encoded, picture.width, picture.height, 3, picture.rgb.data(),
                              picture.width * 3) ||
      !encoded.complete)
    throw std::bad_alloc();
  out.write(encoded.bytes);
}

} // namespace entropy_simplify

#endif // ENTROPY_SIMPLIFY_RENDER_PNG_H
