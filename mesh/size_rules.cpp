#include "mesh/size_rules.h"

#include <algorithm>

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;

}  // namespace

SizeRules SizeRules::from(const Model& model, const MeshOptions& options) {
  SizeRules rules;
  rules.sizeMin = options.sizeMin;
  rules.sizeMax = options.sizeMax;
  rules.factor = options.sizeFactor > 0 ? options.sizeFactor : 1;
  rules.fromPoints = options.sizeFromPoints;
  rules.extendFromBoundary = options.sizeExtendFromBoundary;
  const BoundingBox box = model.boundingBox();
  const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
  rules.defaultSize = diagonal > 0 ? diagonal / 10 : 1;
  return rules;
}

std::pair<double, double> SizeRules::curveEndSizes(const ModelPoint& start,
                                                   const ModelPoint& end) const {
  if (!fromPoints) return {kUnbounded, kUnbounded};
  const double a = start.meshSize > 0 ? start.meshSize : 0;
  const double b = end.meshSize > 0 ? end.meshSize : 0;
  if (a == 0 && b == 0) return {defaultSize, defaultSize};
  return {a > 0 ? a : kUnbounded, b > 0 ? b : kUnbounded};
}

double SizeRules::pointSize(const ModelPoint& p) const {
  if (!fromPoints) return kUnbounded;
  return p.meshSize > 0 ? p.meshSize : defaultSize;
}

double SizeRules::finish(double rawSize) const {
  // The lower bound wins when the bounds contradict each other.
  return std::max(std::min(rawSize, sizeMax), sizeMin) * factor;
}

}  // namespace geomesh
