#include "mesh/frontal_refinement.h"

#include <algorithm>
#include <cmath>

namespace geomesh {
namespace {

// A triangle is good once its circumradius is below this multiple of the circumradius of the
// equilateral triangle of the target size.
constexpr double kAcceptRatio = 1.4;
// A new point closer than this fraction of the target size to a vertex is not inserted.
constexpr double kMinSpacing = 0.5;
constexpr double kSqrt3 = 1.7320508075688772;

enum class State : std::uint8_t { Outside, Waiting, Active, Accepted };

struct HeapEntry {
  float ratio;
  std::uint32_t triangle;
  std::uint32_t stamp;
  friend bool operator<(const HeapEntry& a, const HeapEntry& b) {
    if (a.ratio != b.ratio) return a.ratio < b.ratio;
    return a.triangle > b.triangle;  // deterministic tie-break
  }
};

Vec2 sub(Vec2 a, Vec2 b) { return {a.u - b.u, a.v - b.v}; }
double length(Vec2 a) { return std::hypot(a.u, a.v); }

Vec2 circumcenter(Vec2 a, Vec2 b, Vec2 c) {
  const Vec2 ab = sub(b, a), ac = sub(c, a);
  const double d = 2 * (ab.u * ac.v - ab.v * ac.u);
  const double ab2 = ab.u * ab.u + ab.v * ab.v, ac2 = ac.u * ac.u + ac.v * ac.v;
  return {a.u + (ac.v * ab2 - ab.v * ac2) / d, a.v + (ab.u * ac2 - ac.u * ab2) / d};
}

class FrontalRefiner {
 public:
  FrontalRefiner(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                 std::vector<double>& sizes)
      : tri_(tri), inside_(inside), sizes_(sizes) {}

  void run() {
    const std::uint32_t n = static_cast<std::uint32_t>(tri_.triangleCount());
    state_.assign(n, State::Outside);
    stamp_.assign(n, 0);
    for (std::uint32_t t = 0; t < n; ++t)
      if (inside_[t]) state_[t] = isGood(t) ? State::Accepted : State::Waiting;
    for (std::uint32_t t = 0; t < n; ++t) activateIfOnFront(t);
    while (!heap_.empty()) {
      std::pop_heap(heap_.begin(), heap_.end());
      const HeapEntry e = heap_.back();
      heap_.pop_back();
      if (stamp_[e.triangle] != e.stamp || state_[e.triangle] != State::Active) continue;
      if (!advanceFront(e.triangle)) state_[e.triangle] = State::Accepted;
    }
  }

 private:
  Vec2 p(std::uint32_t t, int i) const { return tri_.point(tri_.vertex(3 * t + i)); }
  double targetSize(std::uint32_t t) const {
    return (sizes_[tri_.vertex(3 * t)] + sizes_[tri_.vertex(3 * t + 1)] +
            sizes_[tri_.vertex(3 * t + 2)]) / 3;
  }
  double ratio(std::uint32_t t) const {
    const Vec2 a = p(t, 0), b = p(t, 1), c = p(t, 2);
    const double area2 = std::abs((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u));
    const double radius = length(sub(b, a)) * length(sub(c, b)) * length(sub(a, c)) / (2 * area2);
    return radius * kSqrt3 / targetSize(t);
  }
  bool isGood(std::uint32_t t) const { return ratio(t) < kAcceptRatio; }

  bool isFrontEdge(std::uint32_t corner) const {
    if (tri_.kind(corner) != EdgeKind::Free) return true;
    const std::uint32_t across = tri_.neighbour(corner);
    return across != kNone && state_[across / 3] == State::Accepted;
  }

  void activateIfOnFront(std::uint32_t t) {
    if (state_[t] != State::Waiting) return;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      if (isFrontEdge(c)) {
        state_[t] = State::Active;
        heap_.push_back({static_cast<float>(ratio(t)), t, stamp_[t]});
        std::push_heap(heap_.begin(), heap_.end());
        return;
      }
    }
  }

  // The front edge of t best suited to build on: the shortest one.
  std::uint32_t frontCorner(std::uint32_t t) const {
    std::uint32_t best = kNone;
    double bestLength = 0;
    for (std::uint32_t c = 3 * t; c < 3 * t + 3; ++c) {
      if (!isFrontEdge(c)) continue;
      const double l = length(sub(p(t, (c + 2) % 3), p(t, (c + 1) % 3)));
      if (best == kNone || l < bestLength) best = c, bestLength = l;
    }
    return best;
  }

  // Where to put the new point in front of the edge of `corner` (Rebay's placement).
  Vec2 frontPoint(std::uint32_t t, std::uint32_t corner) const {
    const std::uint32_t va = tri_.vertex(3 * t + (corner + 1) % 3);
    const std::uint32_t vb = tri_.vertex(3 * t + (corner + 2) % 3);
    const Vec2 a = tri_.point(va), b = tri_.point(vb);
    const Vec2 mid{0.5 * (a.u + b.u), 0.5 * (a.v + b.v)};
    const Vec2 ab = sub(b, a);
    const double half = 0.5 * length(ab);
    const Vec2 inward{-ab.v / (2 * half), ab.u / (2 * half)};
    const Vec2 center = circumcenter(p(t, 0), p(t, 1), p(t, 2));
    const double q = std::max(length(sub(center, mid)), 1e-300);
    const double target = 0.5 * (sizes_[va] + sizes_[vb]) / kSqrt3;
    const double rho = std::min(std::max(target, half), (half * half + q * q) / (2 * q));
    const double d = rho + std::sqrt(std::max(rho * rho - half * half, 0.0));
    return {mid.u + d * inward.u, mid.v + d * inward.v};
  }

  // Size at x interpolated linearly in triangle t.
  double interpolatedSize(std::uint32_t t, Vec2 x) const {
    const Vec2 a = p(t, 0), b = p(t, 1), c = p(t, 2);
    const double det = (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
    const double l1 = ((x.u - a.u) * (c.v - a.v) - (x.v - a.v) * (c.u - a.u)) / det;
    const double l2 = ((b.u - a.u) * (x.v - a.v) - (b.v - a.v) * (x.u - a.u)) / det;
    const double l0 = 1 - l1 - l2;
    return l0 * sizes_[tri_.vertex(3 * t)] + l1 * sizes_[tri_.vertex(3 * t + 1)] +
           l2 * sizes_[tri_.vertex(3 * t + 2)];
  }

  bool tooClose(std::uint32_t t, Vec2 x, double size) const {
    for (int i = 0; i < 3; ++i)
      if (length(sub(p(t, i), x)) < kMinSpacing * size) return true;
    return false;
  }

  bool advanceFront(std::uint32_t t) {
    const std::uint32_t corner = frontCorner(t);
    if (corner == kNone) return false;
    const Vec2 x = frontPoint(t, corner);
    const std::uint32_t found = tri_.locate(x, t);
    if (found == kNone || !inside_[found]) return false;
    const double size = interpolatedSize(found, x);
    if (!(size > 0) || tooClose(found, x, size)) return false;
    const std::uint32_t v = tri_.addPoint(x);
    sizes_.push_back(size);
    if (tri_.insert(v, found) != Triangulation2D::InsertStatus::Inserted) {
      // The point stays unused (no triangle refers to it).
      return false;
    }
    updateAfterInsertion();
    return true;
  }

  void updateAfterInsertion() {
    for (std::uint32_t t : tri_.created()) {
      if (t >= state_.size()) {
        state_.resize(t + 1, State::Outside);
        stamp_.resize(t + 1, 0);
        inside_.resize(t + 1, 0);
      }
      inside_[t] = 1;
      ++stamp_[t];
      state_[t] = isGood(t) ? State::Accepted : State::Waiting;
    }
    for (std::uint32_t t : tri_.created()) activateIfOnFront(t);
    for (std::uint32_t corner : tri_.cavityRim())
      if (corner != kNone) activateIfOnFront(corner / 3);
  }

  Triangulation2D& tri_;
  std::vector<std::uint8_t>& inside_;
  std::vector<double>& sizes_;
  std::vector<State> state_;
  std::vector<std::uint32_t> stamp_;
  std::vector<HeapEntry> heap_;
};

}  // namespace

void refineFrontal(Triangulation2D& tri, std::vector<std::uint8_t>& inside,
                   std::vector<double>& sizes) {
  FrontalRefiner(tri, inside, sizes).run();
}

}  // namespace geomesh
