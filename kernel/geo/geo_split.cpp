// Split Curve: a curve of the built-in kernel cut into pieces at some of its own points.
#include <algorithm>
#include <cstdlib>

#include "kernel/geo/geo_detail.h"
#include "kernel/geo/geo_factory.h"

namespace geomesh {

using geo_detail::fail;

namespace {

// The pieces of `points` between the cuts: each runs from one cut (or the first point) to the
// next (or the last point), sharing its end points with its neighbours.
std::vector<std::vector<int>> piecesBetween(const std::vector<int>& points,
                                            const std::vector<int>& cuts) {
  std::vector<std::vector<int>> pieces{{points.front()}};
  for (std::size_t i = 1; i < points.size(); ++i) {
    pieces.back().push_back(points[i]);
    const bool cut = std::find(cuts.begin(), cuts.end(), points[i]) != cuts.end();
    if (cut && i + 1 < points.size()) pieces.push_back({points[i]});
  }
  return pieces;
}

}  // namespace

std::vector<int> GeoFactory::splitCurve(int tag, const std::vector<int>& points) {
  const auto found = curves_.find(tag);
  if (found == curves_.end()) fail("Split Curve: curve ", tag, " is not defined");
  const Curve curve = found->second;
  const bool splittable =
      curve.knots.empty() && (curve.kind == CurveKind::Spline || curve.kind == CurveKind::BSpline ||
                              curve.kind == CurveKind::Bezier || curve.kind == CurveKind::Line);
  if (!splittable)
    fail("Split Curve: curve ", tag, " is not a spline or a line through points; only those split");
  std::vector<int> cuts;
  for (int p : points) cuts.push_back(std::abs(p));
  const auto pieces = piecesBetween(curve.points, cuts);
  if (pieces.size() == 1) return {tag};  // none of the points is inside the curve
  curves_.erase(tag);
  std::vector<int> tags;
  for (const std::vector<int>& piece : pieces) {
    const int pieceTag = maxTag(1) + 1;
    curves_[pieceTag] = Curve{pieceTag, curve.kind, piece};
    noteTag(1, pieceTag);
    tags.push_back(pieceTag);
  }
  replaceCurveInLoops(tag, tags);
  return tags;
}

// Every use of curve `tag` in a curve loop or a surface's loops becomes the chain of pieces
// (reversed where the curve was).
void GeoFactory::replaceCurveInLoops(int tag, const std::vector<int>& pieces) {
  auto replaceIn = [&](std::vector<int>& loop) {
    std::vector<int> replaced;
    for (int c : loop) {
      if (std::abs(c) != tag) {
        replaced.push_back(c);
        continue;
      }
      const std::vector<int> chain = c >= 0 ? pieces : geo_detail::reversedChain(pieces);
      replaced.insert(replaced.end(), chain.begin(), chain.end());
    }
    loop = std::move(replaced);
  };
  for (auto& [loopTag, loop] : curveLoops_) replaceIn(loop);
  for (auto& [surfaceTag, surface] : surfaces_)
    for (std::vector<int>& loop : surface.loops) replaceIn(loop);
}

}  // namespace geomesh
