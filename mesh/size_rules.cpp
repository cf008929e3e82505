#include "mesh/size_rules.h"

#include <algorithm>

namespace geomesh {

SizeRules SizeRules::from(const Model& model, const MeshOptions& options) {
  SizeRules rules;
  rules.sizeMin = options.sizeMin;
  rules.sizeMax = options.sizeMax;
  rules.factor = options.sizeFactor > 0 ? options.sizeFactor : 1;
  rules.fromPoints = options.sizeFromPoints;
  const BoundingBox box = model.boundingBox();
  const double diagonal = box.empty() ? 0 : distance(box.min, box.max);
  rules.defaultSize = diagonal > 0 ? diagonal / 10 : 1;
  return rules;
}

double SizeRules::pointSize(const ModelPoint& p) const {
  return fromPoints && p.meshSize > 0 ? p.meshSize : defaultSize;
}

double SizeRules::finish(double rawSize) const {
  // The lower bound wins when the bounds contradict each other.
  return std::max(std::min(rawSize, sizeMax), sizeMin) * factor;
}

}  // namespace geomesh
