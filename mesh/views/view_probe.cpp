// ViewProbe: a bucket grid over a view's elements, point location and linear interpolation.
#include "mesh/views/view_probe.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace geomesh::post {
namespace {

constexpr int kMaxCorners = 8;
constexpr int kNewtonIterations = 40;
// A point off the plane (or line) of a 2D (1D) element by up to this fraction of the
// element's diameter still belongs to it, projected onto it.
constexpr double kOffPlaneFraction = 0.1;

// Reference coordinates: lines u in [0,1]; triangles and tetrahedra the unit simplex;
// quadrangles and hexahedra the unit square and cube; prisms the unit triangle times [0,1];
// pyramids the base [-1,1]^2 at w = 0 and the apex at w = 1. Corners in MSH order.
struct ShapeValues {
  double n[kMaxCorners];
  double du[kMaxCorners];
  double dv[kMaxCorners];
  double dw[kMaxCorners];
};

void lineFunctions(const double* r, ShapeValues& s) {
  s.n[0] = 1 - r[0], s.n[1] = r[0];
  s.du[0] = -1, s.du[1] = 1;
}

void triangleFunctions(const double* r, ShapeValues& s) {
  s.n[0] = 1 - r[0] - r[1], s.n[1] = r[0], s.n[2] = r[1];
  s.du[0] = -1, s.du[1] = 1, s.du[2] = 0;
  s.dv[0] = -1, s.dv[1] = 0, s.dv[2] = 1;
}

void quadrangleFunctions(const double* r, ShapeValues& s) {
  static constexpr int kU[4] = {0, 1, 1, 0}, kV[4] = {0, 0, 1, 1};
  for (int i = 0; i < 4; ++i) {
    const double fu = kU[i] ? r[0] : 1 - r[0], fv = kV[i] ? r[1] : 1 - r[1];
    s.n[i] = fu * fv;
    s.du[i] = (kU[i] ? 1 : -1) * fv;
    s.dv[i] = (kV[i] ? 1 : -1) * fu;
  }
}

void tetrahedronFunctions(const double* r, ShapeValues& s) {
  s.n[0] = 1 - r[0] - r[1] - r[2], s.n[1] = r[0], s.n[2] = r[1], s.n[3] = r[2];
  for (int i = 0; i < 4; ++i) {
    s.du[i] = i == 1 ? 1 : i == 0 ? -1 : 0;
    s.dv[i] = i == 2 ? 1 : i == 0 ? -1 : 0;
    s.dw[i] = i == 3 ? 1 : i == 0 ? -1 : 0;
  }
}

// A base shape (its `corners` functions in u, v) times [0, 1] in w: the base's corners at
// w = 0, then again at w = 1.
void extrudedFunctions(const ShapeValues& base, int corners, const double* r, ShapeValues& s) {
  for (int i = 0; i < 2 * corners; ++i) {
    const int b = i % corners;
    const bool top = i >= corners;
    const double fw = top ? r[2] : 1 - r[2];
    s.n[i] = base.n[b] * fw;
    s.du[i] = base.du[b] * fw;
    s.dv[i] = base.dv[b] * fw;
    s.dw[i] = base.n[b] * (top ? 1 : -1);
  }
}

void hexahedronFunctions(const double* r, ShapeValues& s) {
  ShapeValues base;
  quadrangleFunctions(r, base);
  extrudedFunctions(base, 4, r, s);
}

void prismFunctions(const double* r, ShapeValues& s) {
  ShapeValues base;
  triangleFunctions(r, base);
  extrudedFunctions(base, 3, r, s);
}

// The rational pyramid functions (1 + xi u - w)(1 + eta v - w) / (4 (1 - w)) and w: they
// reproduce every affine function of (u, v, w).
void pyramidFunctions(const double* r, ShapeValues& s) {
  static constexpr double kXi[4] = {-1, 1, 1, -1}, kEta[4] = {-1, -1, 1, 1};
  const double w = std::min(r[2], 1 - 1e-12), t = 1 - w;
  for (int i = 0; i < 4; ++i) {
    const double a = 1 + kXi[i] * r[0] - w, b = 1 + kEta[i] * r[1] - w;
    s.n[i] = a * b / (4 * t);
    s.du[i] = kXi[i] * b / (4 * t);
    s.dv[i] = kEta[i] * a / (4 * t);
    s.dw[i] = (a * b / t - a - b) / (4 * t);
  }
  s.n[4] = w, s.du[4] = 0, s.dv[4] = 0, s.dw[4] = 1;
  if (r[2] >= 1 - 1e-12) s.n[0] = s.n[1] = s.n[2] = s.n[3] = 0, s.n[4] = 1;  // the apex
}

void shapeFunctions(ElementShape shape, const double* r, ShapeValues& s) {
  switch (shape) {
    case ElementShape::Point:
      s.n[0] = 1;
      return;
    case ElementShape::Line:
      return lineFunctions(r, s);
    case ElementShape::Triangle:
      return triangleFunctions(r, s);
    case ElementShape::Quadrangle:
      return quadrangleFunctions(r, s);
    case ElementShape::Tetrahedron:
      return tetrahedronFunctions(r, s);
    case ElementShape::Hexahedron:
      return hexahedronFunctions(r, s);
    case ElementShape::Prism:
      return prismFunctions(r, s);
    case ElementShape::Pyramid:
      return pyramidFunctions(r, s);
  }
}

// Where the search starts: the reference element's centroid.
void referenceCentre(ElementShape shape, double* r) {
  switch (shape) {
    case ElementShape::Triangle:
      r[0] = r[1] = 1.0 / 3;
      return;
    case ElementShape::Tetrahedron:
      r[0] = r[1] = r[2] = 0.25;
      return;
    case ElementShape::Prism:
      r[0] = r[1] = 1.0 / 3, r[2] = 0.5;
      return;
    case ElementShape::Pyramid:
      r[0] = r[1] = 0, r[2] = 0.25;
      return;
    default:
      r[0] = r[1] = r[2] = 0.5;
      return;
  }
}

// How far reference coordinates lie outside the reference element (0 inside).
double outsideBy(ElementShape shape, const double* r) {
  const double u = r[0], v = r[1], w = r[2];
  auto below = [](double x, double low) { return std::max(0.0, low - x); };
  switch (shape) {
    case ElementShape::Point:
      return 0;
    case ElementShape::Line:
      return std::max(below(u, 0), u - 1);
    case ElementShape::Triangle:
      return std::max({below(u, 0), below(v, 0), u + v - 1});
    case ElementShape::Quadrangle:
      return std::max({below(u, 0), below(v, 0), u - 1, v - 1});
    case ElementShape::Tetrahedron:
      return std::max({below(u, 0), below(v, 0), below(w, 0), u + v + w - 1});
    case ElementShape::Hexahedron:
      return std::max({below(u, 0), below(v, 0), below(w, 0), u - 1, v - 1, w - 1});
    case ElementShape::Prism:
      return std::max({below(u, 0), below(v, 0), u + v - 1, below(w, 0), w - 1});
    case ElementShape::Pyramid:
      return std::max({below(w, 0), w - 1, std::abs(u) - (1 - w), std::abs(v) - (1 - w)}) / 2;
  }
  return 0;
}

// Solves the d x d symmetric system a x = b (d <= 3) by Cramer's rule; false if singular.
bool solveSmall(int d, const double a[3][3], const double* b, double* x) {
  if (d == 1) {
    if (!(std::abs(a[0][0]) > 0)) return false;
    x[0] = b[0] / a[0][0];
    return true;
  }
  if (d == 2) {
    const double det = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    if (!(std::abs(det) > 0)) return false;
    x[0] = (b[0] * a[1][1] - a[0][1] * b[1]) / det;
    x[1] = (a[0][0] * b[1] - b[0] * a[1][0]) / det;
    return true;
  }
  const double det = a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
                     a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
                     a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
  if (!(std::abs(det) > 0)) return false;
  for (int k = 0; k < 3; ++k) {
    double m[3][3];
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) m[i][j] = j == k ? b[i] : a[i][j];
    x[k] = (m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])) /
           det;
  }
  return true;
}

// An element as the probe keeps it: corners, their values at the probed step, its box
// (widened by its tolerance) and its diameter.
struct ProbeElement {
  Vec3 lo, hi;
  std::uint32_t corners = 0;  // offset of its corners in Index::points
  std::uint32_t values = 0;   // offset of its corner values in Index::values
  ElementShape shape = ElementShape::Point;
  std::uint8_t components = 1;
  double diameter = 0;
};

// A point located in an element: the shape function weights and how well it fits.
struct Location {
  double weights[kMaxCorners] = {};
  double misfit = 0;  // distance outside the element plus distance off its plane/line
};

double vecComponent(Vec3 v, int k) {
  return k == 0 ? v.x : k == 1 ? v.y : v.z;
}

}  // namespace

struct ViewProbe::Index {
  std::vector<ProbeElement> elements;
  std::vector<Vec3> points;
  std::vector<double> values;
  std::vector<double> nodeScalars;        // per entry of `points`: the scalar (norm) there
  std::vector<std::uint32_t> nodeValues;  // per entry of `points`: its first value
  std::vector<std::uint8_t> nodeComponents;
  double tolerance = 0;
  Vec3 lo, hi;
  int cells[3] = {1, 1, 1};
  double cellSize[3] = {1, 1, 1};
  std::vector<std::uint32_t> elementStart, elementItems;  // per cell: elements meeting it
  std::vector<std::uint32_t> pointStart, pointItems;      // per cell: corners in it

  void gather(const View& view, int step, int dimension);
  void buildGrid();
  Vec3 offElementReach(const ProbeElement& e) const;
  int cellCoordinate(Vec3 p, int axis) const;
  std::size_t cellOf(int i, int j, int k) const {
    return (std::size_t(k) * std::size_t(cells[1]) + std::size_t(j)) * std::size_t(cells[0]) +
           std::size_t(i);
  }
  std::optional<Location> locate(const ProbeElement& e, Vec3 p) const;
  const ProbeElement* find(Vec3 p, Location& where) const;
  std::optional<std::size_t> nearestPoint(Vec3 p) const;
};

void ViewProbe::Index::gather(const View& view, int step, int dimension) {
  for (const ElementList& l : view.lists) {
    const int d = shapeDimension(l.shape);
    if (l.size() == 0 || l.steps <= step || (dimension >= 0 && d != dimension) ||
        l.values.size() < l.size() * l.valuesPerElement() ||
        l.nodesPerElement < cornerCount(l.shape))
      continue;
    const int corners = cornerCount(l.shape), c = l.components();
    for (std::size_t e = 0; e < l.size(); ++e) {
      ProbeElement pe;
      pe.shape = l.shape;
      pe.components = std::uint8_t(c);
      pe.corners = std::uint32_t(points.size());
      pe.values = std::uint32_t(values.size());
      for (int i = 0; i < corners; ++i) {
        const double* x = &l.coordinates[3 * (e * std::size_t(l.nodesPerElement) + std::size_t(i))];
        points.push_back({x[0], x[1], x[2]});
        nodeValues.push_back(std::uint32_t(values.size()));
        nodeComponents.push_back(std::uint8_t(c));
        double sum = 0;
        for (int k = 0; k < c; ++k) {
          const double v = l.value(e, step, i, k);
          values.push_back(v);
          sum += v * v;
        }
        nodeScalars.push_back(c == 1 ? values.back() : std::sqrt(sum));
      }
      elements.push_back(pe);
    }
  }
}

// How far, along each axis, a point off a line or a surface element (by up to
// kOffPlaneFraction of its diameter, across it) may lie from its box.
Vec3 ViewProbe::Index::offElementReach(const ProbeElement& e) const {
  const int d = shapeDimension(e.shape);
  if (d != 1 && d != 2) return {};
  const double reach = kOffPlaneFraction * e.diameter;
  const Vec3* x = &points[e.corners];
  if (d == 1) {
    const Vec3 t = normalized(x[1] - x[0]);
    auto across = [&](double c) { return reach * std::sqrt(std::max(0.0, 1 - c * c)); };
    return {across(t.x), across(t.y), across(t.z)};
  }
  const bool quad = e.shape == ElementShape::Quadrangle;
  const Vec3 n =
      normalized(quad ? cross(x[2] - x[0], x[3] - x[1]) : cross(x[1] - x[0], x[2] - x[0]));
  if (!(norm(n) > 0)) return {reach, reach, reach};
  return {reach * std::abs(n.x), reach * std::abs(n.y), reach * std::abs(n.z)};
}

void ViewProbe::Index::buildGrid() {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Vec3 vlo{inf, inf, inf}, vhi{-inf, -inf, -inf};
  for (const Vec3& x : points) {
    vlo = {std::min(vlo.x, x.x), std::min(vlo.y, x.y), std::min(vlo.z, x.z)};
    vhi = {std::max(vhi.x, x.x), std::max(vhi.y, x.y), std::max(vhi.z, x.z)};
  }
  if (points.empty()) vlo = vhi = {};
  tolerance = 1e-6 * distance(vlo, vhi);
  if (!(tolerance > 0)) tolerance = 1e-12;
  lo = vlo, hi = vhi;
  for (ProbeElement& e : elements) {
    const int n = cornerCount(e.shape);
    Vec3 a = points[e.corners], b = a;
    for (int i = 1; i < n; ++i) {
      const Vec3 x = points[e.corners + std::uint32_t(i)];
      a = {std::min(a.x, x.x), std::min(a.y, x.y), std::min(a.z, x.z)};
      b = {std::max(b.x, x.x), std::max(b.y, x.y), std::max(b.z, x.z)};
    }
    e.diameter = distance(a, b);
    const Vec3 widen = offElementReach(e) + Vec3{tolerance, tolerance, tolerance};
    e.lo = a - widen;
    e.hi = b + widen;
    lo = {std::min(lo.x, e.lo.x), std::min(lo.y, e.lo.y), std::min(lo.z, e.lo.z)};
    hi = {std::max(hi.x, e.hi.x), std::max(hi.y, e.hi.y), std::max(hi.z, e.hi.z)};
  }
  // About two cells per element, cubic over the axes the view's nodes span (a flat view gets
  // one layer of cells across its plane); the grid covers the widened boxes.
  const double extent[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
  const double nodeExtent[3] = {vhi.x - vlo.x, vhi.y - vlo.y, vhi.z - vlo.z};
  const double span = std::max({nodeExtent[0], nodeExtent[1], nodeExtent[2]});
  double volume = 1;
  int axes = 0;
  for (double x : nodeExtent)
    if (x > 1e-9 * span) volume *= x, ++axes;
  const double n = 2.0 * double(std::max<std::size_t>(elements.size(), 1));
  const double side = axes > 0 ? std::pow(volume / n, 1.0 / axes) : 1;
  for (int a = 0; a < 3; ++a) {
    const bool spanned = nodeExtent[a] > 1e-9 * span && side > 0;
    cells[a] = spanned ? int(std::clamp(std::ceil(extent[a] / side), 1.0, 2048.0)) : 1;
    cellSize[a] = extent[a] > 0 ? extent[a] / cells[a] : 1;
  }
  const std::size_t cellCount =
      std::size_t(cells[0]) * std::size_t(cells[1]) * std::size_t(cells[2]);
  // Two passes (count, fill) over the cells each element's box meets.
  auto forCells = [&](Vec3 a, Vec3 b, auto&& visit) {
    const int i0 = cellCoordinate(a, 0), i1 = cellCoordinate(b, 0);
    const int j0 = cellCoordinate(a, 1), j1 = cellCoordinate(b, 1);
    const int k0 = cellCoordinate(a, 2), k1 = cellCoordinate(b, 2);
    for (int k = k0; k <= k1; ++k)
      for (int j = j0; j <= j1; ++j)
        for (int i = i0; i <= i1; ++i) visit(cellOf(i, j, k));
  };
  auto fill = [&](std::vector<std::uint32_t>& start, std::vector<std::uint32_t>& items,
                  std::size_t count, auto&& box) {
    start.assign(cellCount + 1, 0);
    for (std::size_t e = 0; e < count; ++e) box(e, [&](std::size_t c) { ++start[c + 1]; });
    for (std::size_t c = 0; c < cellCount; ++c) start[c + 1] += start[c];
    items.resize(start.back());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    for (std::size_t e = 0; e < count; ++e)
      box(e, [&](std::size_t c) { items[next[c]++] = std::uint32_t(e); });
  };
  fill(elementStart, elementItems, elements.size(),
       [&](std::size_t e, auto&& visit) { forCells(elements[e].lo, elements[e].hi, visit); });
  fill(pointStart, pointItems, points.size(),
       [&](std::size_t i, auto&& visit) { forCells(points[i], points[i], visit); });
}

int ViewProbe::Index::cellCoordinate(Vec3 p, int axis) const {
  const double x = vecComponent(p, axis) - vecComponent(lo, axis);
  const double c = std::floor(x / cellSize[axis]);
  if (!(c > 0)) return 0;  // below the grid, or not a number
  return int(std::min(c, double(cells[axis] - 1)));
}

// Finds reference coordinates by Gauss-Newton on |x(r) - p|^2 (exact in one step for
// simplices); for 1D and 2D elements the remaining residual is the distance off the element.
std::optional<Location> ViewProbe::Index::locate(const ProbeElement& e, Vec3 p) const {
  const int n = cornerCount(e.shape), d = shapeDimension(e.shape);
  const Vec3* x = &points[e.corners];
  Location loc;
  if (d == 0) {
    loc.misfit = distance(p, x[0]);
    loc.weights[0] = 1;
    return loc.misfit <= tolerance ? std::optional(loc) : std::nullopt;
  }
  const bool affine = e.shape == ElementShape::Line || e.shape == ElementShape::Triangle ||
                      e.shape == ElementShape::Tetrahedron;
  double r[3] = {0, 0, 0};
  referenceCentre(e.shape, r);
  ShapeValues s{};
  Vec3 residual;
  for (int it = 0; it < kNewtonIterations; ++it) {
    shapeFunctions(e.shape, r, s);
    Vec3 at{}, jac[3] = {};
    const double* derivatives[3] = {s.du, s.dv, s.dw};
    for (int i = 0; i < n; ++i) {
      at += s.n[i] * x[i];
      for (int k = 0; k < d; ++k) jac[k] += derivatives[k][i] * x[i];
    }
    residual = p - at;
    double a[3][3], b[3], step[3];
    for (int k = 0; k < d; ++k) {
      b[k] = dot(jac[k], residual);
      for (int l = 0; l < d; ++l) a[k][l] = dot(jac[k], jac[l]);
    }
    if (!solveSmall(d, a, b, step)) return std::nullopt;
    double change = 0;
    for (int k = 0; k < d; ++k) r[k] += step[k], change = std::max(change, std::abs(step[k]));
    if (!std::isfinite(change) || std::abs(r[0]) + std::abs(r[1]) + std::abs(r[2]) > 1e3)
      return std::nullopt;
    if (change < 1e-14 || affine) break;  // one step solves an affine map
  }
  shapeFunctions(e.shape, r, s);
  Vec3 at{};
  for (int i = 0; i < n; ++i) at += s.n[i] * x[i];
  const double off = distance(p, at);
  const double outside = outsideBy(e.shape, r) * e.diameter;
  const double offLimit = tolerance + (d < 3 ? kOffPlaneFraction * e.diameter : 0);
  if (outside > tolerance || off > offLimit) return std::nullopt;
  std::copy(s.n, s.n + n, loc.weights);
  loc.misfit = outside + off;
  return loc;
}

// The element holding p: the highest dimension first, then the best fit, then the first.
const ProbeElement* ViewProbe::Index::find(Vec3 p, Location& where) const {
  if (elements.empty() || p.x < lo.x || p.y < lo.y || p.z < lo.z || p.x > hi.x || p.y > hi.y ||
      p.z > hi.z)
    return nullptr;
  const std::size_t c = cellOf(cellCoordinate(p, 0), cellCoordinate(p, 1), cellCoordinate(p, 2));
  const ProbeElement* best = nullptr;
  for (std::uint32_t k = elementStart[c]; k < elementStart[c + 1]; ++k) {
    const ProbeElement& e = elements[elementItems[k]];
    if (p.x < e.lo.x || p.y < e.lo.y || p.z < e.lo.z || p.x > e.hi.x || p.y > e.hi.y ||
        p.z > e.hi.z)
      continue;
    if (best && shapeDimension(e.shape) < shapeDimension(best->shape)) continue;
    const std::optional<Location> loc = locate(e, p);
    if (!loc) continue;
    const bool higher = best && shapeDimension(e.shape) > shapeDimension(best->shape);
    if (!best || higher || loc->misfit < where.misfit) best = &e, where = *loc;
  }
  return best;
}

// The corner nearest to p, by rings of cells around the cell of q, p clamped into the grid
// (first of equals). For x in the grid |p - x|^2 >= |p - q|^2 + |q - x|^2, so once the cells
// within a ring are searched, the rest lie beyond sqrt(|p - q|^2 + gap^2), gap the distance
// from q to the ring's outer faces that have cells beyond them.
std::optional<std::size_t> ViewProbe::Index::nearestPoint(Vec3 p) const {
  if (points.empty()) return std::nullopt;
  const int centre[3] = {cellCoordinate(p, 0), cellCoordinate(p, 1), cellCoordinate(p, 2)};
  const Vec3 q{std::clamp(p.x, lo.x, hi.x), std::clamp(p.y, lo.y, hi.y),
               std::clamp(p.z, lo.z, hi.z)};
  const double pq2 = dot(p - q, p - q);
  std::optional<std::size_t> best;
  double bestDistance = std::numeric_limits<double>::infinity();
  auto visit = [&](int i, int j, int k) {
    const std::size_t c = cellOf(i, j, k);
    for (std::uint32_t m = pointStart[c]; m < pointStart[c + 1]; ++m) {
      const double dd = distance(p, points[pointItems[m]]);
      if (dd < bestDistance || (best && dd == bestDistance && pointItems[m] < *best))
        bestDistance = dd, best = pointItems[m];
    }
  };
  for (int ring = 0;; ++ring) {
    int from[3], to[3];
    for (int a = 0; a < 3; ++a)
      from[a] = std::max(centre[a] - ring, 0), to[a] = std::min(centre[a] + ring, cells[a] - 1);
    for (int k = from[2]; k <= to[2]; ++k)
      for (int j = from[1]; j <= to[1]; ++j) {
        const bool shell = std::abs(k - centre[2]) == ring || std::abs(j - centre[1]) == ring;
        if (shell) {
          for (int i = from[0]; i <= to[0]; ++i) visit(i, j, k);
        } else {
          if (centre[0] - ring >= 0) visit(centre[0] - ring, j, k);
          if (ring > 0 && centre[0] + ring < cells[0]) visit(centre[0] + ring, j, k);
        }
      }
    double gap = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3; ++a) {
      const double qa = vecComponent(q, a), base = vecComponent(lo, a);
      if (from[a] > 0) gap = std::min(gap, qa - (base + from[a] * cellSize[a]));
      if (to[a] < cells[a] - 1) gap = std::min(gap, base + (to[a] + 1) * cellSize[a] - qa);
    }
    if (!std::isfinite(gap)) break;  // every cell searched
    if (best && bestDistance * bestDistance <= pq2 + std::max(gap, 0.0) * std::max(gap, 0.0)) break;
  }
  return best;
}

ViewProbe::ViewProbe(const View& view, int step, int dimension)
    : index_(std::make_unique<Index>()) {
  index_->gather(view, std::max(step, 0), dimension);
  index_->buildGrid();
}

ViewProbe::~ViewProbe() = default;
ViewProbe::ViewProbe(ViewProbe&&) noexcept = default;
ViewProbe& ViewProbe::operator=(ViewProbe&&) noexcept = default;

std::optional<std::array<double, 9>> ViewProbe::components(Vec3 point, int* count) const {
  Location where;
  const ProbeElement* e = index_->find(point, where);
  if (!e) return std::nullopt;
  std::array<double, 9> out{};
  const int c = e->components, n = cornerCount(e->shape);
  for (int i = 0; i < n; ++i)
    for (int k = 0; k < c; ++k)
      out[std::size_t(k)] += where.weights[i] * index_->values[e->values + std::size_t(i * c + k)];
  if (count) *count = c;
  return out;
}

std::optional<double> ViewProbe::scalar(Vec3 point) const {
  int count = 0;
  const auto v = components(point, &count);
  if (!v) return std::nullopt;
  if (count == 1) return (*v)[0];
  double sum = 0;
  for (int k = 0; k < count; ++k) sum += (*v)[std::size_t(k)] * (*v)[std::size_t(k)];
  return std::sqrt(sum);
}

std::optional<std::array<double, 6>> ViewProbe::tensor(Vec3 point) const {
  int count = 0;
  const auto v = components(point, &count);
  if (!v || count != 9) return std::nullopt;
  const auto& m = *v;
  return std::array<double, 6>{m[0], (m[1] + m[3]) / 2, (m[2] + m[6]) / 2,
                               m[4], (m[5] + m[7]) / 2, m[8]};
}

std::optional<double> ViewProbe::nearestScalar(Vec3 point) const {
  const std::optional<std::size_t> i = index_->nearestPoint(point);
  if (!i) return std::nullopt;
  return index_->nodeScalars[*i];
}

std::optional<std::array<double, 9>> ViewProbe::nearestComponents(Vec3 point, int* count) const {
  const std::optional<std::size_t> i = index_->nearestPoint(point);
  if (!i) return std::nullopt;
  std::array<double, 9> out{};
  const int c = index_->nodeComponents[*i];
  for (int k = 0; k < c; ++k)
    out[std::size_t(k)] = index_->values[index_->nodeValues[*i] + std::size_t(k)];
  if (count) *count = c;
  return out;
}

}  // namespace geomesh::post
