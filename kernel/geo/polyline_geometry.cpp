// PolylineGeometry: points and tangents along a chain of segments.
#include "kernel/geo/polyline_geometry.h"

#include <algorithm>
#include <stdexcept>

namespace geomesh {

PolylineGeometry::PolylineGeometry(std::vector<Vec3> points) : points_(std::move(points)) {
  if (points_.size() < 2) throw std::invalid_argument("a polyline needs at least 2 points");
  starts_.push_back(0);
  for (std::size_t i = 1; i < points_.size(); ++i)
    starts_.push_back(starts_.back() + distance(points_[i - 1], points_[i]));
  const double length = starts_.back();
  for (double& s : starts_) s = length > 0 ? s / length : 0;
  starts_.back() = 1;
}

std::size_t PolylineGeometry::segmentAt(double t) const {
  const auto after = std::upper_bound(starts_.begin() + 1, starts_.end() - 1, t);
  return static_cast<std::size_t>(after - starts_.begin()) - 1;
}

Vec3 PolylineGeometry::point(double t) const {
  const std::size_t i = segmentAt(t);
  const double width = starts_[i + 1] - starts_[i];
  const double s = width > 0 ? (t - starts_[i]) / width : 0;
  return points_[i] + s * (points_[i + 1] - points_[i]);
}

Vec3 PolylineGeometry::firstDerivative(double t) const {
  const std::size_t i = segmentAt(t);
  const double width = starts_[i + 1] - starts_[i];
  return width > 0 ? (1 / width) * (points_[i + 1] - points_[i]) : Vec3{};
}

}  // namespace geomesh
