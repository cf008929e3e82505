// BoundaryExtension: the listed curves' 1D meshes, surface samples, and the extension law.
#include "mesh/sizes/boundary_extension.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "mesh/sizes/point_cloud.h"
#include "mesh/sizes/size_rules.h"

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;

struct EdgeList {
  std::vector<Vec3> midpoints;
  std::vector<double> lengths;
};

// The nodes of a curve's 1D mesh as the 1D stage places them from the end points' sizes: the
// size varies linearly in arc length between them (SizeRules), the curve gets as many
// segments as the integral of 1/size, rounded up unless within 1% above a whole number (at
// least SizeRules::minimumSegments, 3 on a closed curve), and the nodes split that integral
// into equal parts. (The 1D stage also bounds the size by a background field or curvature
// where they apply; these nodes leave such bounds out.)
std::vector<Vec3> curveNodes(const Model& model, const ModelCurve& curve, const SizeRules& rules) {
  const ModelPoint* start = model.point(curve.startPoint);
  const ModelPoint* end = model.point(curve.endPoint);
  const CurveGeometry& g = *curve.geometry;
  if (!start || !end || g.isDegenerate()) return {};
  constexpr int kPieces = 512;
  const Interval r = g.range();
  std::vector<Vec3> points(kPieces + 1);
  std::vector<double> length(kPieces + 1, 0.0);
  for (int k = 0; k <= kPieces; ++k) {
    points[k] = g.point(r.min + (r.max - r.min) * k / kPieces);
    if (k > 0) length[k] = length[k - 1] + distance(points[k - 1], points[k]);
  }
  const auto ends = rules.curveEndSizes(*start, *end);
  const double startSize = ends.first, endSize = ends.second;
  const double total = length[kPieces];
  const auto sizeAt = [&](double s) {
    const double w = total > 0 ? s / total : 0;
    return rules.finish((1 - w) * startSize + w * endSize);
  };
  std::vector<double> integral(kPieces + 1, 0.0);
  for (int k = 1; k <= kPieces; ++k)
    integral[k] =
        integral[k - 1] + (length[k] - length[k - 1]) / sizeAt(0.5 * (length[k - 1] + length[k]));
  const bool closed = curve.startPoint == curve.endPoint;
  int segments =
      std::max(static_cast<int>(std::floor(integral[kPieces] + 0.99)), rules.minimumSegments(g));
  segments = std::max(segments, closed ? 3 : 1);
  std::vector<Vec3> nodes{points.front()};
  int piece = 1;
  for (int n = 1; n < segments; ++n) {
    const double target = integral[kPieces] * n / segments;
    while (piece < kPieces && integral[piece] < target) ++piece;
    const double span = integral[piece] - integral[piece - 1];
    const double w = span > 0 ? (target - integral[piece - 1]) / span : 0;
    nodes.push_back(points[piece - 1] + w * (points[piece] - points[piece - 1]));
  }
  nodes.push_back(points.back());
  return nodes;
}

// The edges of the 1D meshes of the curves (curveNodes).
EdgeList curveMeshEdges(const Model& model, const std::vector<int>& curves,
                        const MeshOptions& options) {
  const SizeRules rules = SizeRules::from(model, options);
  EdgeList edges;
  for (int tag : curves) {
    const ModelCurve* curve = model.curve(tag);
    if (!curve || !curve->geometry) continue;
    const std::vector<Vec3> nodes = curveNodes(model, *curve, rules);
    for (std::size_t k = 0; k + 1 < nodes.size(); ++k) {
      edges.midpoints.push_back(0.5 * (nodes[k] + nodes[k + 1]));
      edges.lengths.push_back(distance(nodes[k], nodes[k + 1]));
    }
  }
  return edges;
}

// Samples per parameter direction of a surface: about four per edge length of its boundary,
// within [8, 100].
int surfaceSampling(const ModelSurface& surface, const BoundaryExtension::Edges& boundary) {
  const ParamBox box = surface.geometry->bounds();
  double extent = 0;
  for (double u : {box.u.min, 0.5 * (box.u.min + box.u.max), box.u.max})
    extent = std::max(extent, distance(surface.geometry->point({u, box.v.min}),
                                       surface.geometry->point({u, box.v.max})));
  for (double v : {box.v.min, 0.5 * (box.v.min + box.v.max), box.v.max})
    extent = std::max(extent, distance(surface.geometry->point({box.u.min, v}),
                                       surface.geometry->point({box.u.max, v})));
  double shortest = kUnbounded;
  for (double length : boundary.lengths) shortest = std::min(shortest, length);
  if (!(shortest < kUnbounded) || !(extent > 0)) return 8;
  return static_cast<int>(std::clamp(std::ceil(4 * extent / shortest), 8.0, 100.0));
}

BoundaryExtension::Edges toEdges(EdgeList list) {
  BoundaryExtension::Edges edges;
  edges.lengths = std::move(list.lengths);
  edges.midpoints = std::make_unique<PointCloud>(std::move(list.midpoints));
  return edges;
}

}  // namespace

double BoundaryExtension::Edges::at(Vec3 p, const Law& law) const {
  if (!midpoints || midpoints->empty()) return kUnbounded;
  const PointCloud::Nearest nearest = midpoints->nearest(p);
  if (!(nearest.distance < law.distMax)) return law.sizeMax;
  const double f = std::pow((law.distMax - nearest.distance) / law.distMax, law.power);
  return f * lengths[nearest.index] + (1 - f) * law.sizeMax;
}

BoundaryExtension::BoundaryExtension(const Model& model, const std::vector<int>& curves,
                                     const std::vector<int>& surfaces, Law law,
                                     const MeshOptions& options)
    : law_(law) {
  curveEdges_ = toEdges(curveMeshEdges(model, curves, options));
  EdgeList sampled;
  for (int tag : surfaces) {
    const ModelSurface* surface = model.surface(tag);
    if (!surface || !surface->geometry) continue;
    std::vector<int> own;
    for (int c : model.boundary({2, tag})) own.push_back(std::abs(c));
    const Edges boundary = toEdges(curveMeshEdges(model, own, options));
    const int n = surfaceSampling(*surface, boundary);
    const ParamBox box = surface->geometry->bounds();
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const double u = box.u.min + (box.u.max - box.u.min) * i / n;
        const double v = box.v.min + (box.v.max - box.v.min) * j / n;
        const Vec3 p = surface->geometry->point({u, v});
        const double size = boundary.at(p, law);
        if (!(size < kUnbounded)) continue;
        sampled.midpoints.push_back(p);
        sampled.lengths.push_back(size);
      }
  }
  surfaceEdges_ = toEdges(std::move(sampled));
}

BoundaryExtension::~BoundaryExtension() = default;

double BoundaryExtension::at(Vec3 p, int dim) const {
  if (dim == 2) return curveEdges_.at(p, law_);
  if (dim == 3) return surfaceEdges_.at(p, law_);
  return kUnbounded;
}

}  // namespace geomesh
