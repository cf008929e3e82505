// Jacobian bounds as in Johnen, Remacle and Geuzaine, "Geometrical validity of curvilinear
// finite elements" (2013): the determinant is a polynomial on the reference element, so its
// Bernstein coefficients, computed from samples at a lattice of its degree, bound it.
#include "mesh/high_order/jacobian.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "mesh/high_order/per_type.h"
#include "mesh/high_order/reference_element.h"
#include "mesh/high_order/bernstein.h"
#include "mesh/high_order/shape_functions.h"

namespace geomesh {
namespace {

using Point = std::array<double, 3>;
using Gradient = std::array<double, 3>;

// Shape function gradients at a list of reference points, node-fastest.
std::vector<Gradient> gradientsAt(ElementType type, std::span<const Point> points) {
  const ShapeFunctions& shape = shapeFunctions(type);
  const auto n = static_cast<std::size_t>(shape.size());
  std::vector<Gradient> out(points.size() * n);
  for (std::size_t q = 0; q < points.size(); ++q)
    shape.gradients(points[q], std::span(out).subspan(q * n, n));
  return out;
}

// What the determinant of a surface or line element is measured along.
struct Frame {
  int dim = 3;
  Vec3 axis;  // unit normal (surfaces) or chord direction (lines)
};

Frame frameOf(ElementType type, std::span<const Vec3> nodes) {
  Frame f{dimension(type), {}};
  if (f.dim == 2) f.axis = normalized(cross(nodes[1] - nodes[0], nodes[2] - nodes[0]));
  if (f.dim == 1) f.axis = normalized(nodes[1] - nodes[0]);
  return f;
}

// Columns of dx/dxi: the derivatives of the map along each reference axis.
std::array<Vec3, 3> tangents(std::span<const Vec3> nodes, const Gradient* g) {
  std::array<Vec3, 3> t{};
  for (std::size_t i = 0; i < nodes.size(); ++i)
    for (int d = 0; d < 3; ++d) t[d] += g[i][d] * nodes[i];
  return t;
}

double determinant(const Frame& f, std::span<const Vec3> nodes, const Gradient* g) {
  const std::array<Vec3, 3> t = tangents(nodes, g);
  switch (f.dim) {
    case 1: return dot(t[0], f.axis);
    case 2: return dot(cross(t[0], t[1]), f.axis);
    default: return dot(t[0], cross(t[1], t[2]));
  }
}

// sqrt(det(J^T J)): the length, area or volume element.
double metric(int dim, std::span<const Vec3> nodes, const Gradient* g) {
  const std::array<Vec3, 3> t = tangents(nodes, g);
  switch (dim) {
    case 1: return norm(t[0]);
    case 2: return norm(cross(t[0], t[1]));
    default: return std::abs(dot(t[0], cross(t[1], t[2])));
  }
}

// The determinant's polynomial space as Bernstein factors: degree 2(p-1) on triangles,
// 3(p-1) on tetrahedra, 2p-1 per axis on quadrangles, 3p-1 on hexahedra; on prisms 3p-2 on
// the triangle and 3p-1 along the line.
std::vector<SimplexFactor> determinantFactors(ElementType type) {
  const int p = order(type);
  switch (family(type)) {
    case ElementFamily::Line: return {{1, p - 1, 0}};
    case ElementFamily::Triangle: return {{2, 2 * p - 2, 0}};
    case ElementFamily::Tet: return {{3, 3 * p - 3, 0}};
    case ElementFamily::Quad: return {{1, 2 * p - 1, 0}, {1, 2 * p - 1, 1}};
    case ElementFamily::Hex: return {{1, 3 * p - 1, 0}, {1, 3 * p - 1, 1}, {1, 3 * p - 1, 2}};
    case ElementFamily::Prism: return {{2, 3 * p - 2, 0}, {1, 3 * p - 1, 2}};
    default: throw std::logic_error("no Bezier bounds for this family");
  }
}

ProductDomain referenceDomain(ElementFamily f) {
  using S = std::array<Point, 4>;
  const S segment{{{-1, 0, 0}, {1, 0, 0}}};
  const S triangle{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  const S tet{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  switch (f) {
    case ElementFamily::Line: return {{segment}};
    case ElementFamily::Triangle: return {{triangle}};
    case ElementFamily::Tet: return {{tet}};
    case ElementFamily::Quad: return {{segment, segment}};
    case ElementFamily::Hex: return {{segment, segment, segment}};
    case ElementFamily::Prism: return {{triangle, segment}};
    default: return {};
  }
}

// The Bernstein basis of a type's determinant and the shape gradients at its lattice on the
// whole reference element.
struct BezierSampler {
  BernsteinProduct bernstein;
  ProductDomain reference;
  std::vector<Gradient> gradients;

  explicit BezierSampler(ElementType type)
      : bernstein(determinantFactors(type)), reference(referenceDomain(family(type))) {
    std::vector<Point> points(bernstein.size());
    for (std::size_t s = 0; s < points.size(); ++s) points[s] = bernstein.point(reference, s);
    gradients = gradientsAt(type, points);
  }
};

// Subdivision stops at this depth, or when the element has used up its share of work (samples
// times nodes squared, the cost of shape gradients away from the cached lattice, about 0.2 s);
// the bound kept is then the coefficients' (conservative: it may call a barely valid element
// invalid, never the reverse). Note that the conversion from samples to coefficients
// amplifies rounding with the degree, up to 1e-4 relative for hexahedra of order 4.
constexpr int kMaxDepth = 6;
constexpr std::size_t kWorkBudget = std::size_t{1} << 28;

struct BezierSearch {
  ElementType type;
  std::span<const Vec3> nodes;
  Frame frame;
  const BernsteinProduct& bernstein;
  std::size_t workLeft;

  std::vector<double> samplesOn(const ProductDomain& domain) const {
    std::vector<Point> points(bernstein.size());
    for (std::size_t s = 0; s < points.size(); ++s) points[s] = bernstein.point(domain, s);
    const std::vector<Gradient> g = gradientsAt(type, points);
    std::vector<double> out(points.size());
    for (std::size_t s = 0; s < out.size(); ++s)
      out[s] = determinant(frame, nodes, &g[s * nodes.size()]);
    return out;
  }

  JacobianRange bound(const ProductDomain& domain, const std::vector<double>& samples,
                      int depth) {
    const std::vector<double> c = bernstein.coefficients(samples);
    const auto [lo, hi] = std::minmax_element(c.begin(), c.end());
    const JacobianRange here{*lo, *hi};
    // Positive coefficients prove validity; a non-positive sample proves invalidity.
    if (here.min > 0 || *std::min_element(samples.begin(), samples.end()) <= 0) return here;
    if (depth == kMaxDepth) return here;
    const std::vector<ProductDomain> children = bernstein.subdivide(domain);
    const std::size_t work = children.size() * bernstein.size() * nodes.size() * nodes.size();
    if (work > workLeft) return here;
    workLeft -= work;
    JacobianRange sub{std::numeric_limits<double>::infinity(),
                      -std::numeric_limits<double>::infinity()};
    for (const ProductDomain& child : children) {
      const JacobianRange r = bound(child, samplesOn(child), depth + 1);
      sub.min = std::min(sub.min, r.min);
      sub.max = std::max(sub.max, r.max);
    }
    return {std::max(here.min, sub.min), std::min(here.max, sub.max)};
  }
};

// Pyramids: the map is not one of the tensor or simplex spaces above, so the determinant is
// only sampled, at the pyramid lattice of order 2p + 2 (corners, apex and interior), and the
// range is that of the samples: an estimate, not a bound.
struct PyramidSampler {
  std::vector<Gradient> gradients;
  std::size_t points = 0;

  explicit PyramidSampler(ElementType type) {
    const int q = 2 * order(type) + 2;
    std::vector<Point> at;
    for (int k = 0; k <= q; ++k)
      for (int j = 0; j <= q - k; ++j)
        for (int i = 0; i <= q - k; ++i)
          at.push_back({static_cast<double>(2 * i + k - q) / q,
                        static_cast<double>(2 * j + k - q) / q, static_cast<double>(k) / q});
    points = at.size();
    gradients = gradientsAt(type, at);
  }
};

// Gauss-Legendre points and weights on [-1, 1] (Newton on the Legendre polynomial).
void gaussLegendre(int n, std::vector<double>& x, std::vector<double>& w) {
  x.assign(n, 0);
  w.assign(n, 0);
  for (int i = 0; i < n; ++i) {
    double t = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), slope = 1;
    for (int iteration = 0; iteration < 100; ++iteration) {
      double p0 = 1, p1 = t;  // P_0 and P_1, then up to P_n
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2 * k - 1) * t * p1 - (k - 1) * p0) / k;
        p0 = p1, p1 = p2;
      }
      slope = n * (t * p1 - p0) / (t * t - 1);
      const double step = p1 / slope;
      t -= step;
      if (std::abs(step) < 1e-16) break;
    }
    x[i] = t;
    w[i] = 2 / ((1 - t * t) * slope * slope);
  }
}

// Points per axis: exact for the determinant's degree along an axis (plus the degree of the
// collapse from a cube for simplices and pyramids), with one to spare.
int pointsPerAxis(ElementType type) {
  const int p = order(type);
  int degree = 0;
  switch (family(type)) {
    case ElementFamily::Line: degree = p - 1; break;
    case ElementFamily::Triangle: degree = 2 * p - 1; break;
    case ElementFamily::Tet: degree = 3 * p - 1; break;
    case ElementFamily::Quad: degree = 2 * p - 1; break;
    case ElementFamily::Hex:
    case ElementFamily::Prism: degree = 3 * p - 1; break;
    default: degree = 6 * p + 2; break;  // pyramids: x^p y^p terms, collapsed
  }
  // |x_u| and |x_u x x_v| are square roots, not polynomials: more points for those (lines
  // are cheap, and a strongly bent one needs many).
  const int spare = dimension(type) == 1 ? 8 * p : dimension(type) == 2 ? 2 * p : 0;
  return degree / 2 + 2 + spare;
}

// A quadrature rule for a type's reference element with its shape gradients. Simplices and
// pyramids are the images of a cube collapsed along its last axes.
struct MeasureRule {
  std::vector<Point> points;
  std::vector<double> weights;
  std::vector<Gradient> gradients;

  explicit MeasureRule(ElementType type) {
    std::vector<double> x, w;
    gaussLegendre(pointsPerAxis(type), x, w);
    const std::size_t n = x.size();
    const ElementFamily f = family(type);
    const int dim = dimension(type);
    for (std::size_t k = 0; k < (dim == 3 ? n : 1); ++k)
      for (std::size_t j = 0; j < (dim >= 2 ? n : 1); ++j)
        for (std::size_t i = 0; i < n; ++i) {
          const Point c{x[i], dim >= 2 ? x[j] : 0, dim == 3 ? x[k] : 0};
          const double weight = w[i] * (dim >= 2 ? w[j] : 1) * (dim == 3 ? w[k] : 1);
          add(f, c, weight);
        }
    gradients = gradientsAt(type, points);
  }

  // Maps a point c of [-1, 1]^d (weight w) onto the reference element.
  void add(ElementFamily f, const Point& c, double w) {
    const double a = (c[0] + 1) / 2, b = (c[1] + 1) / 2, e = (c[2] + 1) / 2;
    switch (f) {
      case ElementFamily::Triangle:
        push({a * (1 - b), b, 0}, w * (1 - b) / 4);
        break;
      case ElementFamily::Tet:
        push({a * (1 - b) * (1 - e), b * (1 - e), e}, w * (1 - b) * (1 - e) * (1 - e) / 8);
        break;
      case ElementFamily::Prism: push({a * (1 - b), b, c[2]}, w * (1 - b) / 4); break;
      case ElementFamily::Pyramid:
        push({c[0] * (1 - e), c[1] * (1 - e), e}, w * (1 - e) * (1 - e) / 2);
        break;
      default: push(c, w); break;
    }
  }
  void push(const Point& p, double w) {
    points.push_back(p);
    weights.push_back(w);
  }
};

bool isSimplex(ElementFamily f) {
  return f == ElementFamily::Line || f == ElementFamily::Triangle || f == ElementFamily::Tet;
}

void requireNodes(ElementType type, std::span<const Vec3> nodes) {
  if (static_cast<int>(nodes.size()) != nodeCount(type))
    throw std::invalid_argument(std::string(elementName(type)) + " needs " +
                                std::to_string(nodeCount(type)) + " nodes");
}

}  // namespace

double jacobianDeterminant(ElementType type, std::span<const Vec3> nodes, const Point& xi) {
  requireNodes(type, nodes);
  if (dimension(type) == 0) return 1;
  std::vector<Gradient> g(nodes.size());
  shapeFunctions(type).gradients(xi, g);
  return determinant(frameOf(type, nodes), nodes, g.data());
}

bool isStraight(ElementType type, std::span<const Vec3> nodes) {
  requireNodes(type, nodes);
  const ReferenceElement& ref = referenceElement(type);
  const std::size_t v = vertexCount(type);
  const std::span<const Vec3> corners = nodes.first(v);
  double size = 0;
  for (std::size_t k = 1; k < v; ++k) size = std::max(size, distance(corners[0], corners[k]));
  for (std::size_t k = v; k < nodes.size(); ++k)
    if (distance(nodes[k], linearImage(ref.family, ref.xi[k], corners)) > 1e-12 * size)
      return false;
  return true;
}

JacobianRange jacobianRange(ElementType type, std::span<const Vec3> nodes) {
  requireNodes(type, nodes);
  if (dimension(type) == 0) return {1, 1};
  // A node at no finite place (a damaged file) makes no element: no search for a bound.
  constexpr double kInfinity = std::numeric_limits<double>::infinity();
  for (const Vec3& x : nodes)
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(x.z))
      return {-kInfinity, kInfinity};
  const Frame frame = frameOf(type, nodes);
  const std::size_t n = nodes.size();
  if (family(type) == ElementFamily::Pyramid) {
    const PyramidSampler& sampler = perType<PyramidSampler>(type);
    JacobianRange r{std::numeric_limits<double>::infinity(),
                    -std::numeric_limits<double>::infinity()};
    for (std::size_t s = 0; s < sampler.points; ++s) {
      const double d = determinant(frame, nodes, &sampler.gradients[s * n]);
      r.min = std::min(r.min, d);
      r.max = std::max(r.max, d);
    }
    return r;
  }
  const BezierSampler& sampler = perType<BezierSampler>(type);
  if (isSimplex(family(type)) && isStraight(type, nodes)) {
    const double d = determinant(frame, nodes, sampler.gradients.data());
    return {d, d};
  }
  std::vector<double> samples(sampler.bernstein.size());
  for (std::size_t s = 0; s < samples.size(); ++s)
    samples[s] = determinant(frame, nodes, &sampler.gradients[s * n]);
  BezierSearch search{type, nodes, frame, sampler.bernstein, kWorkBudget};
  return search.bound(sampler.reference, samples, 0);
}

double scaledJacobian(ElementType type, std::span<const Vec3> nodes) {
  const JacobianRange r = jacobianRange(type, nodes);
  if (!std::isfinite(r.min) || !std::isfinite(r.max)) return -1;
  const double scale = std::max(std::abs(r.min), std::abs(r.max));
  return scale > 0 ? r.min / scale : 0;
}

double elementMeasure(ElementType type, std::span<const Vec3> nodes) {
  requireNodes(type, nodes);
  const int dim = dimension(type);
  if (dim == 0) return 0;
  if (isSimplex(family(type)) && isStraight(type, nodes)) {
    // A constant determinant times the reference element's measure (2, 1/2, 1/6).
    constexpr double kReference[] = {0, 2, 0.5, 1.0 / 6};
    std::vector<Gradient> g(nodes.size());
    shapeFunctions(type).gradients({}, g);
    return kReference[dim] * std::abs(determinant(frameOf(type, nodes), nodes, g.data()));
  }
  const MeasureRule& rule = perType<MeasureRule>(type);
  double total = 0;
  for (std::size_t q = 0; q < rule.points.size(); ++q)
    total += rule.weights[q] * metric(dim, nodes, &rule.gradients[q * nodes.size()]);
  return total;
}

}  // namespace geomesh
