// Lagrange bases as the inverse of a Vandermonde matrix of monomials at the reference nodes.
#include "mesh/high_order/shape_functions.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mesh/high_order/per_type.h"
#include "mesh/high_order/dense_inverse.h"
#include "mesh/high_order/reference_element.h"

namespace geomesh {
namespace {

constexpr int kMaxExponent = 8;

// The complete polynomial space of a family at order p, lowest total degree first.
std::vector<Monomial> completeSpace(ElementFamily f, int p) {
  std::vector<Monomial> out;
  for (int c = 0; c <= p; ++c)
    for (int b = 0; b <= p; ++b)
      for (int a = 0; a <= p; ++a) {
        bool in = false;
        switch (f) {
          case ElementFamily::Point: in = a + b + c == 0; break;
          case ElementFamily::Line: in = b == 0 && c == 0; break;
          case ElementFamily::Triangle: in = c == 0 && a + b <= p; break;
          case ElementFamily::Quad: in = c == 0; break;
          case ElementFamily::Tet: in = a + b + c <= p; break;
          case ElementFamily::Hex: in = true; break;
          case ElementFamily::Prism: in = a + b <= p; break;
          case ElementFamily::Pyramid: in = a <= p - c && b <= p - c; break;
        }
        if (in) out.push_back({a, b, c});
      }
  std::stable_sort(out.begin(), out.end(), [](const Monomial& l, const Monomial& r) {
    return l[0] + l[1] + l[2] < r[0] + r[1] + r[2];
  });
  return out;
}

double power(double x, int k) {
  double r = 1;
  for (int i = 0; i < k; ++i) r *= x;
  return r;
}

double monomialAt(const Monomial& m, const std::array<double, 3>& xi) {
  return power(xi[0], m[0]) * power(xi[1], m[1]) * power(xi[2], m[2]);
}

// The monomials of `candidates`, in order, that are independent of the ones kept before them
// on the nodes (Gram-Schmidt on their values at the nodes, twice for accuracy).
std::vector<Monomial> independentOnNodes(const std::vector<Monomial>& candidates,
                                         const std::vector<std::array<double, 3>>& nodes) {
  const std::size_t n = nodes.size();
  std::vector<std::vector<double>> basis;
  std::vector<Monomial> kept;
  for (const Monomial& m : candidates) {
    if (kept.size() == n) break;
    std::vector<double> v(n);
    for (std::size_t k = 0; k < n; ++k) v[k] = monomialAt(m, nodes[k]);
    double original = 0;
    for (double x : v) original += x * x;
    for (int pass = 0; pass < 2; ++pass)
      for (const std::vector<double>& q : basis) {
        double d = 0;
        for (std::size_t k = 0; k < n; ++k) d += q[k] * v[k];
        for (std::size_t k = 0; k < n; ++k) v[k] -= d * q[k];
      }
    double left = 0;
    for (double x : v) left += x * x;
    if (left <= 1e-16 * original) continue;
    for (double& x : v) x /= std::sqrt(left);
    basis.push_back(std::move(v));
    kept.push_back(m);
  }
  return kept;
}

// x^k and its derivative k x^(k-1) for k = 0..kMaxExponent, per coordinate.
struct Powers {
  std::array<std::array<double, kMaxExponent + 1>, 3> value{}, slope{};
  explicit Powers(const std::array<double, 3>& xi) {
    for (int d = 0; d < 3; ++d) {
      value[d][0] = 1, slope[d][0] = 0;
      for (int k = 1; k <= kMaxExponent; ++k) {
        value[d][k] = value[d][k - 1] * xi[d];
        slope[d][k] = k * value[d][k - 1];
      }
    }
  }
};

}  // namespace

ShapeFunctions::ShapeFunctions(ElementType type) : type_(type) {
  const ReferenceElement& ref = referenceElement(type);
  const std::size_t n = ref.xi.size();
  const std::vector<Monomial> complete = completeSpace(ref.family, ref.order);
  monomials_ = isSerendipity(type) ? independentOnNodes(complete, ref.xi) : complete;
  const std::string name = elementName(type);
  if (monomials_.size() != n)
    throw std::logic_error("no polynomial space with one monomial per node for " + name);
  inverse_.resize(n * n);
  for (std::size_t k = 0; k < n; ++k)
    for (std::size_t m = 0; m < n; ++m) inverse_[k * n + m] = monomialAt(monomials_[m], ref.xi[k]);
  if (!invertDense(inverse_, n, 1e-10))
    throw std::logic_error("the polynomial space of " + name + " is not unisolvent on its nodes");
}

void ShapeFunctions::values(const std::array<double, 3>& xi, std::span<double> out) const {
  const std::size_t n = monomials_.size();
  const Powers pw(xi);
  std::fill(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n), 0.0);
  for (std::size_t m = 0; m < n; ++m) {
    const Monomial& e = monomials_[m];
    const double v = pw.value[0][e[0]] * pw.value[1][e[1]] * pw.value[2][e[2]];
    const double* row = &inverse_[m * n];
    for (std::size_t i = 0; i < n; ++i) out[i] += row[i] * v;
  }
}

void ShapeFunctions::gradients(const std::array<double, 3>& xi,
                               std::span<std::array<double, 3>> out) const {
  const std::size_t n = monomials_.size();
  const Powers pw(xi);
  std::fill(out.begin(), out.begin() + static_cast<std::ptrdiff_t>(n), std::array<double, 3>{});
  for (std::size_t m = 0; m < n; ++m) {
    const Monomial& e = monomials_[m];
    const double x = pw.value[0][e[0]], y = pw.value[1][e[1]], z = pw.value[2][e[2]];
    const double dx = pw.slope[0][e[0]] * y * z;
    const double dy = x * pw.slope[1][e[1]] * z;
    const double dz = x * y * pw.slope[2][e[2]];
    const double* row = &inverse_[m * n];
    for (std::size_t i = 0; i < n; ++i) {
      out[i][0] += row[i] * dx;
      out[i][1] += row[i] * dy;
      out[i][2] += row[i] * dz;
    }
  }
}

const ShapeFunctions& shapeFunctions(ElementType type) { return perType<ShapeFunctions>(type); }

}  // namespace geomesh
