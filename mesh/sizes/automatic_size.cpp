// AutomaticSize: curvature and gap sources sampled on the model, and their graded minimum.
#include "mesh/sizes/automatic_size.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <unordered_map>

#include "mesh/sizes/size_rules.h"

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;
constexpr int kMaxCurveSamples = 2000;
constexpr int kMaxSurfaceSamples = 100;  // per parameter direction

// A sampled place on a curve or surface: its entity, parameters and direction (the unit
// tangent on a curve, the unit normal on a surface).
struct Sample {
  Vec3 point;
  Vec3 direction;
  int entity;
  Vec2 uv;  // u: the curve parameter on a curve
};

std::vector<Sample> curveSamples(const Model& model, double spacing) {
  std::vector<Sample> samples;
  for (const auto& [tag, curve] : model.curves()) {
    if (!curve.geometry || curve.geometry->isDegenerate()) continue;
    const CurveGeometry& g = *curve.geometry;
    const Interval r = g.range();
    double length = 0;
    constexpr int kProbe = 64;
    for (int k = 0; k < kProbe; ++k)
      length += distance(g.point(r.min + (r.max - r.min) * k / kProbe),
                         g.point(r.min + (r.max - r.min) * (k + 1) / kProbe));
    const int n = static_cast<int>(
        std::clamp(std::ceil(length / spacing), 8.0, static_cast<double>(kMaxCurveSamples)));
    for (int k = 0; k <= n; ++k) {
      const double t = r.min + (r.max - r.min) * k / n;
      samples.push_back({g.point(t), normalized(g.firstDerivative(t)), tag, {t, 0}});
    }
  }
  return samples;
}

std::vector<Sample> surfaceSamples(const Model& model, double spacing) {
  std::vector<Sample> samples;
  for (const auto& [tag, surface] : model.surfaces()) {
    if (!surface.geometry) continue;
    const SurfaceGeometry& g = *surface.geometry;
    const ParamBox box = g.bounds();
    double extent = 0;
    for (double f : {0.0, 0.5, 1.0}) {
      const double u = box.u.min + f * (box.u.max - box.u.min);
      const double v = box.v.min + f * (box.v.max - box.v.min);
      extent = std::max(extent, distance(g.point({u, box.v.min}), g.point({u, box.v.max})));
      extent = std::max(extent, distance(g.point({box.u.min, v}), g.point({box.u.max, v})));
    }
    const int n = static_cast<int>(
        std::clamp(std::ceil(extent / spacing), 8.0, static_cast<double>(kMaxSurfaceSamples)));
    for (int i = 0; i <= n; ++i)
      for (int j = 0; j <= n; ++j) {
        const Vec2 uv{box.u.min + (box.u.max - box.u.min) * i / n,
                      box.v.min + (box.v.max - box.v.min) * j / n};
        const SurfaceDerivatives d = g.firstDerivatives(uv);
        samples.push_back({g.point(uv), normalized(cross(d.du, d.dv)), tag, uv});
      }
  }
  return samples;
}

void addCurvatureSources(const Model& model, const std::vector<Sample>& curves,
                         const std::vector<Sample>& surfaces, int perCircle, double bulk,
                         std::vector<AutomaticSize::Source>& out) {
  if (perCircle <= 0) return;
  const auto add = [&](Vec3 p, double curvature) {
    if (!(curvature > 0)) return;
    const double size = 2 * std::numbers::pi / (perCircle * curvature);
    if (size < bulk) out.push_back({p, size});
  };
  for (const Sample& s : curves)
    add(s.point, curveCurvature(*model.curve(s.entity)->geometry, s.uv.u));
  for (const Sample& s : surfaces) {
    const SurfaceGeometry& g = *model.surface(s.entity)->geometry;
    if (!g.isPlane()) add(s.point, surfaceCurvature(g, s.uv));
  }
}

// The boundary of each entity of the sampled dimension, to tell neighbours apart.
std::unordered_map<int, std::vector<int>> boundaries(const Model& model, int dim) {
  std::unordered_map<int, std::vector<int>> result;
  if (dim == 1) {
    for (const auto& [tag, curve] : model.curves())
      result[tag] = {curve.startPoint, curve.endPoint};
  } else {
    for (const auto& entry : model.surfaces()) {
      std::vector<int>& b = result[entry.first];
      for (int c : model.boundary({2, entry.first})) b.push_back(std::abs(c));
    }
  }
  for (auto& entry : result) std::sort(entry.second.begin(), entry.second.end());
  return result;
}

bool shareBoundary(const std::vector<int>& a, const std::vector<int>& b) {
  for (int x : a)
    if (std::binary_search(b.begin(), b.end(), x)) return true;
  return false;
}

// The point of a curve closest to p, by Newton steps from parameter t.
Vec3 closestOnCurve(const CurveGeometry& g, Vec3 p, double t) {
  const Interval r = g.range();
  for (int k = 0; k < 12; ++k) {
    const Vec3 d = g.point(t) - p, d1 = g.firstDerivative(t), d2 = g.secondDerivative(t);
    const double slope = dot(d, d1), curvature = dot(d1, d1) + dot(d, d2);
    if (!(curvature > 0)) break;
    const double next = std::clamp(t - slope / curvature, r.min, r.max);
    if (std::abs(next - t) <= 1e-12 * (1 + std::abs(t))) break;
    t = next;
  }
  return g.point(t);
}

// Buckets of samples on a grid of cells of side `cell`.
class SampleGrid {
 public:
  SampleGrid(const std::vector<Sample>& samples, double cell) : cell_(cell) {
    for (std::uint32_t k = 0; k < samples.size(); ++k)
      cells_[key(samples[k].point, 0, 0, 0)].push_back(k);
  }
  template <class Visit>
  void around(Vec3 p, Visit&& visit) const {
    for (int i = -1; i <= 1; ++i)
      for (int j = -1; j <= 1; ++j)
        for (int k = -1; k <= 1; ++k)
          if (const auto it = cells_.find(key(p, i, j, k)); it != cells_.end())
            for (std::uint32_t s : it->second) visit(s);
  }

 private:
  std::uint64_t key(Vec3 p, int di, int dj, int dk) const {
    const auto index = [&](double x, int d) {
      return static_cast<std::uint64_t>(static_cast<std::int64_t>(std::floor(x / cell_)) + d +
                                        (1 << 20)) &
             0x1fffff;
    };
    return index(p.x, di) << 42 | index(p.y, dj) << 21 | index(p.z, dk);
  }
  double cell_;
  std::unordered_map<std::uint64_t, std::vector<std::uint32_t>> cells_;
};

// A thin gap at each sample: the nearest facing entity that shares no boundary with its own.
void addGapSources(const Model& model, const std::vector<Sample>& samples, int dim, int perGap,
                   double bulk, std::vector<AutomaticSize::Source>& out) {
  const double reach = bulk * perGap;  // wider gaps ask for more than the bulk size
  if (samples.empty() || !(reach > 0)) return;
  const auto bounds = boundaries(model, dim);
  const SampleGrid grid(samples, reach);
  constexpr double kFacing = 0.7;  // cosine between the gap and the normal, at least
  for (const Sample& s : samples) {
    const std::vector<int>& own = bounds.at(s.entity);
    std::unordered_map<int, std::uint32_t> nearest;  // entity -> its sample nearest to s
    grid.around(s.point, [&](std::uint32_t k) {
      const Sample& q = samples[k];
      if (q.entity == s.entity || distance(q.point, s.point) >= reach) return;
      auto [it, inserted] = nearest.try_emplace(q.entity, k);
      if (!inserted && distance(q.point, s.point) < distance(samples[it->second].point, s.point))
        it->second = k;
    });
    double smallest = kUnbounded;
    for (const auto& [entity, k] : nearest) {
      if (shareBoundary(own, bounds.at(entity))) continue;
      const Sample& q = samples[k];
      const Vec3 c = dim == 1 ? closestOnCurve(*model.curve(entity)->geometry, s.point, q.uv.u)
                              : model.surface(entity)->geometry->point(
                                    model.surface(entity)->geometry->project(s.point));
      const double gap = distance(c, s.point);
      if (!(gap > 0) || gap >= reach) continue;
      const double along = std::abs(dot(s.direction, (c - s.point) / gap));
      const bool facing = dim == 1 ? along <= kFacing : along >= kFacing;
      if (facing) smallest = std::min(smallest, gap / perGap);
    }
    if (smallest < bulk) out.push_back({s.point, smallest});
  }
}

double coordinate(Vec3 p, int axis) {
  return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

}  // namespace

std::vector<AutomaticSize::Source> automaticSizeSources(const Model& model,
                                                        const AutomaticSize::Options& o,
                                                        double bulk) {
  const double spacing = bulk / 4;
  const std::vector<Sample> curves = curveSamples(model, spacing);
  const std::vector<Sample> surfaces = surfaceSamples(model, spacing);
  std::vector<AutomaticSize::Source> sources;
  addCurvatureSources(model, curves, surfaces, o.pointsPerCircle, bulk, sources);
  if (o.features && o.pointsPerGap > 0) {
    if (model.volumes().empty())
      addGapSources(model, curves, 1, o.pointsPerGap, bulk, sources);
    else
      addGapSources(model, surfaces, 2, o.pointsPerGap, bulk, sources);
  }
  return sources;
}

AutomaticSize::AutomaticSize(const Model& model, const Options& options) : options_(options) {
  bulk_ = options.hBulk > 0 ? options.hBulk : defaultSizeOf(model.sizeBox());
  rate_ = std::max(options.gradation - 1, 0.0);
  sources_ = automaticSizeSources(model, options, bulk_);
  const std::size_t n = sources_.size();
  boxMin_.resize(n);
  boxMax_.resize(n);
  smallest_.resize(n);
  axis_.assign(n, 0);
  build(0, static_cast<std::uint32_t>(n));
}

void AutomaticSize::build(std::uint32_t begin, std::uint32_t end) {
  if (begin >= end) return;
  Vec3 lo = sources_[begin].point, hi = lo;
  double smallest = kUnbounded;
  for (std::uint32_t k = begin; k < end; ++k) {
    const Vec3 q = sources_[k].point;
    lo = {std::min(lo.x, q.x), std::min(lo.y, q.y), std::min(lo.z, q.z)};
    hi = {std::max(hi.x, q.x), std::max(hi.y, q.y), std::max(hi.z, q.z)};
    smallest = std::min(smallest, sources_[k].size);
  }
  const Vec3 extent = hi - lo;
  const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
  const std::uint32_t mid = begin + (end - begin) / 2;
  std::nth_element(sources_.begin() + begin, sources_.begin() + mid, sources_.begin() + end,
                   [axis](const Source& a, const Source& b) {
                     return coordinate(a.point, axis) < coordinate(b.point, axis);
                   });
  boxMin_[mid] = lo;
  boxMax_[mid] = hi;
  smallest_[mid] = smallest;
  axis_[mid] = static_cast<std::uint8_t>(axis);
  build(begin, mid);
  build(mid + 1, end);
}

double AutomaticSize::bound(Vec3 p, std::uint32_t node) const {
  const Vec3 lo = boxMin_[node], hi = boxMax_[node];
  const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
  const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
  const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
  return smallest_[node] + rate_ * std::sqrt(dx * dx + dy * dy + dz * dz);
}

void AutomaticSize::search(Vec3 p, std::uint32_t begin, std::uint32_t end, double& best) const {
  if (begin >= end) return;
  const std::uint32_t mid = begin + (end - begin) / 2;
  if (bound(p, mid) >= best) return;
  best = std::min(best, sources_[mid].size + rate_ * distance(p, sources_[mid].point));
  const bool lowFirst = coordinate(p, axis_[mid]) < coordinate(sources_[mid].point, axis_[mid]);
  if (lowFirst) {
    search(p, begin, mid, best);
    search(p, mid + 1, end, best);
  } else {
    search(p, mid + 1, end, best);
    search(p, begin, mid, best);
  }
}

double AutomaticSize::at(Vec3 p) const {
  double size = bulk_;
  search(p, 0, static_cast<std::uint32_t>(sources_.size()), size);
  if (options_.hMax > 0) size = std::min(size, options_.hMax);
  if (options_.hMin > 0) size = std::max(size, options_.hMin);
  return size;
}

}  // namespace geomesh
