// BoundaryLayerParameters: reading the options, the heights of the layer and its size law.
#include "mesh/sizes/boundary_layer_field.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "mesh/sizes/field_options.h"
#include "mesh/sizes/point_cloud.h"

namespace geomesh {
namespace {

std::vector<int> integers(const std::vector<double>& values) {
  std::vector<int> out;
  for (double v : values) out.push_back(static_cast<int>(std::lround(v)));
  return out;
}

bool contains(const std::vector<int>& list, int tag) {
  return std::find(list.begin(), list.end(), tag) != list.end();
}

// The Beta law's place of the fraction t of the way, in [0, 1]: nodes packed towards 0, more
// so as Beta approaches 1 from above.
double betaPlace(double beta, double t) {
  const double r = std::pow((beta + 1) / (beta - 1), 1 - t);
  return ((beta + 1) - (beta - 1) * r) / (r + 1);
}

double segmentDistance(Vec3 p, Vec3 a, Vec3 b) {
  const Vec3 ab = b - a;
  const double length2 = dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return distance(p, a + t * ab);
}

constexpr int kSamplesPerCurve = 400;
constexpr int kMaxLayers = 10000;  // a bound against a ratio below 1 never reaching Thickness

}  // namespace

bool BoundaryLayerParameters::hasCurve(int t) const {
  return contains(curves, t);
}
bool BoundaryLayerParameters::excludes(int s) const {
  return contains(excludedSurfaces, s);
}
bool BoundaryLayerParameters::isFanPoint(int p) const {
  return contains(fanPoints, p);
}

int BoundaryLayerParameters::fanElements(int point, int fallback) const {
  for (std::size_t k = 0; k < fanPoints.size() && k < fanPointsSizes.size(); ++k)
    if (fanPoints[k] == point && fanPointsSizes[k] > 0) return fanPointsSizes[k];
  return fallback;
}

double BoundaryLayerParameters::firstHeight(int point) const {
  for (std::size_t k = 0; k < points.size() && k < sizes.size(); ++k)
    if (points[k] == point && sizes[k] > 0) return sizes[k];
  return size;
}

std::vector<double> BoundaryLayerParameters::heights(double first) const {
  std::vector<double> out;
  if (!(first > 0)) return out;
  if (betaLaw) {
    const int n = std::clamp(layers, 1, kMaxLayers);
    if (!(beta > 1)) {  // the law needs Beta above 1: even layers
      for (int k = 1; k <= n; ++k) out.push_back(first * k);
      return out;
    }
    const double scale = first / betaPlace(beta, 1.0 / n);
    for (int k = 1; k <= n; ++k) out.push_back(scale * betaPlace(beta, double(k) / n));
    return out;
  }
  // A layer whose top reaches Thickness (up to rounding) is kept.
  const double limit = thickness * (1 + 1e-12);
  double h = first, top = first;
  while (top <= limit && static_cast<int>(out.size()) < kMaxLayers) {
    out.push_back(top);
    h *= ratio;
    top += h;
  }
  return out;
}

double BoundaryLayerParameters::sizeAt(double d) const {
  return std::min(sizeFar, size + std::max(d, 0.0) * (ratio - 1));
}

CurveDistance::CurveDistance(const Model& model, const std::vector<int>& curves) {
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const ModelCurve* curve = model.curve(curves[c]);
    if (!curve || !curve->geometry) continue;
    const Interval r = curve->geometry->range();
    for (int k = 0; k <= kSamplesPerCurve; ++k) {
      samples_.push_back(curve->geometry->point(r.min + (r.max - r.min) * k / kSamplesPerCurve));
      piece_.push_back(static_cast<int>(c));
    }
  }
  cloud_ = std::make_unique<PointCloud>(samples_);
}

CurveDistance::~CurveDistance() = default;

double CurveDistance::operator()(Vec3 p) const {
  if (samples_.empty()) return 1e22;
  const std::uint32_t k = cloud_->nearest(p).index;
  double best = distance(p, samples_[k]);
  if (k > 0 && piece_[k - 1] == piece_[k])
    best = std::min(best, segmentDistance(p, samples_[k - 1], samples_[k]));
  if (k + 1 < samples_.size() && piece_[k + 1] == piece_[k])
    best = std::min(best, segmentDistance(p, samples_[k], samples_[k + 1]));
  return best;
}

namespace {

// Stores a list option; false for a name that is not one of the field's lists.
bool storeList(BoundaryLayerParameters& p, const std::string& name,
               const std::vector<double>& values) {
  if (name == "CurvesList")
    p.curves = integers(values);
  else if (name == "PointsList")
    p.points = integers(values);
  else if (name == "ExcludedSurfacesList")
    p.excludedSurfaces = integers(values);
  else if (name == "FanPointsList")
    p.fanPoints = integers(values);
  else if (name == "FanPointsSizesList")
    p.fanPointsSizes = integers(values);
  else if (name == "SizesList")
    p.sizes = values;
  else
    return false;
  return true;
}

// Stores a numeric option; false for a name that is not one of the field's.
bool storeNumber(BoundaryLayerParameters& p, const std::string& name, double v) {
  if (name == "Size")
    p.size = v;
  else if (name == "SizeFar")
    p.sizeFar = v;
  else if (name == "Ratio")
    p.ratio = v;
  else if (name == "Thickness")
    p.thickness = v;
  else if (name == "NbLayers")
    p.layers = static_cast<int>(std::lround(v));
  else if (name == "BetaLaw")
    p.betaLaw = v != 0;
  else if (name == "Beta")
    p.beta = v;
  else if (name == "Quads")
    p.quads = v != 0;
  else if (name == "IntersectMetrics")
    p.intersectMetrics = v != 0;
  else if (name == "AnisoMax")
    p.anisoMax = v;
  else
    return false;
  return true;
}

}  // namespace

void readBoundaryLayerOptions(BoundaryLayerParameters& p, const std::string& field,
                              const SizeFieldDefinition& def, MessageSink& log) {
  // Older names this field type alone takes.
  static const std::pair<const char*, const char*> kOlderNames[] = {
      {"thickness", "Thickness"},
      {"ratio", "Ratio"},
      {"ExcludedFaceList", "ExcludedSurfacesList"},
      {"hwall_n_nodes", "SizesList"}};
  for (const auto& [rawName, values] : def.numbers) {
    std::string name = canonicalFieldOption(rawName);
    for (const auto& [older, current] : kOlderNames)
      if (name == older) name = current;
    if (!storeList(p, name, values) &&
        !(values.size() == 1 && storeNumber(p, name, values.front())))
      log.warning(field + "." + rawName + " is not an option of this field type; ignored");
  }
  for (const auto& entry : def.strings)
    log.warning(field + "." + entry.first + " is not an option of this field type; ignored");
}

}  // namespace geomesh
