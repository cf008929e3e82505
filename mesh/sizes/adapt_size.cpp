// AdaptSize: element measures and sizes, the equidistributing sizes, and their nodal field.
#include "mesh/sizes/adapt_size.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;

using post::ElementList;
using post::ElementShape;

Vec3 corner(const ElementList& l, std::size_t e, int i) {
  const double* x = &l.coordinates[3 * (e * std::size_t(l.nodesPerElement) + std::size_t(i))];
  return {x[0], x[1], x[2]};
}

double tetVolume(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return std::abs(dot(b - a, cross(c - a, d - a))) / 6;
}

double triangleArea(Vec3 a, Vec3 b, Vec3 c) {
  return norm(cross(b - a, c - a)) / 2;
}

// Length, area or volume of an element from its corners (split into simplices: exact for
// affine elements).
double measure(const ElementList& l, std::size_t e) {
  Vec3 x[8];
  for (int i = 0; i < post::cornerCount(l.shape); ++i) x[i] = corner(l, e, i);
  switch (l.shape) {
    case ElementShape::Point:
      return 0;
    case ElementShape::Line:
      return distance(x[0], x[1]);
    case ElementShape::Triangle:
      return triangleArea(x[0], x[1], x[2]);
    case ElementShape::Quadrangle:
      return triangleArea(x[0], x[1], x[2]) + triangleArea(x[0], x[2], x[3]);
    case ElementShape::Tetrahedron:
      return tetVolume(x[0], x[1], x[2], x[3]);
    case ElementShape::Hexahedron: {
      static constexpr int kAround[6][2] = {{1, 2}, {2, 3}, {3, 7}, {7, 4}, {4, 5}, {5, 1}};
      double v = 0;
      for (const auto& t : kAround) v += tetVolume(x[0], x[t[0]], x[t[1]], x[6]);
      return v;
    }
    case ElementShape::Prism:
      return tetVolume(x[0], x[1], x[2], x[3]) + tetVolume(x[1], x[2], x[3], x[4]) +
             tetVolume(x[2], x[3], x[4], x[5]);
    case ElementShape::Pyramid:
      return tetVolume(x[0], x[1], x[2], x[4]) + tetVolume(x[0], x[2], x[3], x[4]);
  }
  return 0;
}

// The mean over an element's nodes of its step-0 values (norms for vectors and tensors).
double meanError(const ElementList& l, std::size_t e) {
  double sum = 0;
  const int c = l.components();
  for (int i = 0; i < l.nodesPerElement; ++i) {
    double squares = 0;
    for (int k = 0; k < c; ++k) squares += l.value(e, 0, i, k) * l.value(e, 0, i, k);
    sum += c == 1 ? l.value(e, 0, i, 0) : std::sqrt(squares);
  }
  return std::abs(sum / l.nodesPerElement);
}

// c_d: the measure of the equilateral simplex of unit edge.
double unitMeasure(int d) {
  return d == 1 ? 1 : d == 2 ? std::sqrt(3.0) / 4 : std::sqrt(2.0) / 12;
}

std::optional<std::string> checkOptions(const AdaptOptions& o) {
  if ((o.targetElements > 0) == (o.targetError > 0))
    return "exactly one of TargetElements and TargetError must be positive";
  if (o.order <= 0) return "Order must be positive";
  if (o.dimension == 0 || o.dimension > 3) return "Dimension must be 1, 2 or 3";
  return std::nullopt;
}

bool usable(const ElementList& l) {
  return l.size() > 0 && l.nodesPerElement >= post::cornerCount(l.shape) &&
         l.values.size() >= l.size() * l.valuesPerElement();
}

}  // namespace

std::optional<AdaptedSizes> adaptSizes(const post::View& view, const AdaptOptions& options,
                                       std::string& why) {
  if (const auto bad = checkOptions(options)) return why = *bad, std::nullopt;
  int d = options.dimension;
  if (d < 0)
    for (const ElementList& l : view.lists)
      if (usable(l)) d = std::max(d, post::shapeDimension(l.shape));
  if (d <= 0) return why = "the view holds no line, surface or volume element", std::nullopt;
  AdaptedSizes r;
  r.dimension = d;
  r.unitMeasure = unitMeasure(d);
  for (std::size_t li = 0; li < view.lists.size(); ++li) {
    const ElementList& l = view.lists[li];
    if (!usable(l) || post::shapeDimension(l.shape) != d) continue;
    for (std::size_t e = 0; e < l.size(); ++e) {
      const double m = measure(l, e);
      if (!(m > 0)) continue;
      r.sources.push_back({li, e});
      r.measures.push_back(m);
      r.errors.push_back(meanError(l, e));
      r.sizes.push_back(std::pow(m / r.unitMeasure, 1.0 / d));
    }
  }
  if (r.measures.empty())
    return why = "the view holds no element of dimension " + std::to_string(d), std::nullopt;
  const double k = options.order, p = k + d / 2.0;
  std::vector<double> c(r.measures.size());
  double s = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i] = r.errors[i] / std::pow(r.sizes[i], p);
    s += r.measures[i] * std::pow(c[i], d / p);
  }
  const double mu =
      options.targetElements > 0
          ? std::pow(s / (r.unitMeasure * options.targetElements), 1.0 / d)
          : std::pow(r.unitMeasure * options.targetError * options.targetError / s, 1 / (2 * k));
  double error2 = 0;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const double h = c[i] > 0 ? mu * std::pow(c[i], -1 / p) : kUnbounded;
    if (c[i] > 0) {
      r.predictedElements += r.measures[i] / (r.unitMeasure * std::pow(h, d));
      error2 += r.measures[i] / r.unitMeasure * c[i] * c[i] * std::pow(h, 2 * k);
    }
    r.newSizes.push_back(
        std::min(std::max(std::isfinite(h) ? h : kUnbounded, options.sizeMin), options.sizeMax));
  }
  r.predictedError = std::sqrt(error2);
  return r;
}

// Nodes merged by equal coordinates take the geometric mean of their elements' new sizes.
post::View AdaptSize::nodalSizes(const post::View& view, const AdaptedSizes& sizes) {
  using Key = std::tuple<double, double, double>;
  std::map<Key, std::pair<double, int>> logSums;
  auto key = [](Vec3 x) { return Key{x.x, x.y, x.z}; };
  for (std::size_t i = 0; i < sizes.sources.size(); ++i) {
    const ElementList& l = view.lists[sizes.sources[i].list];
    for (int n = 0; n < post::cornerCount(l.shape); ++n) {
      auto& [sum, count] = logSums[key(corner(l, sizes.sources[i].element, n))];
      sum += std::log(sizes.newSizes[i]);
      ++count;
    }
  }
  post::View nodal;
  for (std::size_t i = 0; i < sizes.sources.size(); ++i) {
    const ElementList& l = view.lists[sizes.sources[i].list];
    ElementList& out = nodal.list(l.shape, post::FieldKind::Scalar);
    for (int n = 0; n < post::cornerCount(l.shape); ++n) {
      const Vec3 x = corner(l, sizes.sources[i].element, n);
      const auto& [sum, count] = logSums[key(x)];
      out.coordinates.insert(out.coordinates.end(), {x.x, x.y, x.z});
      out.values.push_back(std::exp(sum / count));
    }
  }
  return nodal;
}

AdaptSize::AdaptSize(const post::View& view, const AdaptedSizes& sizes, const AdaptOptions& options)
    : probe_(nodalSizes(view, sizes)), sizeMin_(options.sizeMin), sizeMax_(options.sizeMax) {}

double AdaptSize::at(Vec3 p) const {
  std::optional<double> h = probe_.scalar(p);
  if (!h) h = probe_.nearestScalar(p);
  if (!h) return kUnbounded;
  return std::min(std::max(*h, sizeMin_), sizeMax_);
}

}  // namespace geomesh
