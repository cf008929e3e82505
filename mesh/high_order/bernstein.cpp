// Bernstein bases on simplices, combined factor by factor, and the red refinement of simplices.
#include "mesh/high_order/bernstein.h"

#include <stdexcept>

#include "mesh/high_order/dense_inverse.h"

namespace geomesh {
namespace {

using Vertex = std::array<double, 3>;
using Simplex = std::array<Vertex, 4>;
using MultiIndex = std::array<int, 4>;  // exponents of the dim + 1 barycentric coordinates

std::vector<MultiIndex> multiIndices(int dim, int degree) {
  std::vector<MultiIndex> out;
  const int n = degree;
  for (int k = 0; k <= (dim >= 3 ? n : 0); ++k)
    for (int j = 0; j <= (dim >= 2 ? n - k : 0); ++j)
      for (int i = 0; i <= n - j - k; ++i) out.push_back({n - i - j - k, i, j, k});
  return out;
}

double bernstein(const MultiIndex& alpha, const std::array<double, 4>& lambda, int dim) {
  double value = 1;
  int done = 0;
  for (int v = 0; v <= dim; ++v)
    for (int e = 1; e <= alpha[v]; ++e) value *= lambda[v] * ++done / e;  // n! / prod alpha!
  return value;
}

Vertex midpoint(const Vertex& a, const Vertex& b) {
  return {(a[0] + b[0]) / 2, (a[1] + b[1]) / 2, (a[2] + b[2]) / 2};
}

// Red refinement: halves of a segment, four triangles, or eight tetrahedra (the inner
// octahedron cut along the diagonal from midpoint 02 to midpoint 13).
std::vector<Simplex> children(const Simplex& s, int dim) {
  auto m = [&](int a, int b) { return midpoint(s[a], s[b]); };
  if (dim == 1) return {{s[0], m(0, 1)}, {m(0, 1), s[1]}};
  if (dim == 2)
    return {{s[0], m(0, 1), m(0, 2)},
            {m(0, 1), s[1], m(1, 2)},
            {m(0, 2), m(1, 2), s[2]},
            {m(0, 1), m(1, 2), m(0, 2)}};
  const Vertex m01 = m(0, 1), m02 = m(0, 2), m03 = m(0, 3), m12 = m(1, 2), m13 = m(1, 3),
               m23 = m(2, 3);
  return {{s[0], m01, m02, m03}, {m01, s[1], m12, m13}, {m02, m12, s[2], m23},
          {m03, m13, m23, s[3]}, {m02, m13, m01, m03}, {m02, m13, m03, m23},
          {m02, m13, m23, m12},  {m02, m13, m12, m01}};
}

}  // namespace

BernsteinProduct::BernsteinProduct(std::vector<SimplexFactor> shapes) {
  for (const SimplexFactor& shape : shapes) {
    Factor f{shape, {}, {}};
    const std::vector<MultiIndex> lattice = multiIndices(shape.dim, shape.degree);
    for (const MultiIndex& alpha : lattice) {
      std::array<double, 4> lambda{};
      for (int v = 0; v <= shape.dim; ++v)
        lambda[v] = shape.degree == 0 ? 1.0 / (shape.dim + 1)
                                      : static_cast<double>(alpha[v]) / shape.degree;
      f.barycentric.push_back(lambda);
    }
    const std::size_t m = lattice.size();
    f.toBernstein.resize(m * m);
    for (std::size_t s = 0; s < m; ++s)
      for (std::size_t b = 0; b < m; ++b)
        f.toBernstein[s * m + b] = bernstein(lattice[b], f.barycentric[s], shape.dim);
    if (!invertDense(f.toBernstein, m)) throw std::logic_error("singular Bernstein lattice");
    size_ *= m;
    factors_.push_back(std::move(f));
  }
}

std::array<double, 3> BernsteinProduct::point(const ProductDomain& domain, std::size_t s) const {
  std::array<double, 3> xi{};
  for (std::size_t f = factors_.size(); f-- > 0;) {
    const Factor& factor = factors_[f];
    const std::size_t m = factor.barycentric.size();
    const std::array<double, 4>& lambda = factor.barycentric[s % m];
    s /= m;
    for (int c = 0; c < factor.shape.dim; ++c) {
      double x = 0;
      for (int v = 0; v <= factor.shape.dim; ++v) x += lambda[v] * domain.vertices[f][v][c];
      xi[factor.shape.axis + c] = x;
    }
  }
  return xi;
}

std::vector<double> BernsteinProduct::coefficients(std::span<const double> samples) const {
  std::vector<double> data(samples.begin(), samples.end()), line;
  std::size_t stride = size_;
  for (const Factor& factor : factors_) {
    const std::size_t m = factor.barycentric.size();
    stride /= m;
    line.resize(m);
    for (std::size_t outer = 0; outer < size_; outer += m * stride)
      for (std::size_t inner = 0; inner < stride; ++inner) {
        double* at = &data[outer + inner];
        for (std::size_t j = 0; j < m; ++j) line[j] = at[j * stride];
        for (std::size_t k = 0; k < m; ++k) {
          double c = 0;
          for (std::size_t j = 0; j < m; ++j) c += factor.toBernstein[k * m + j] * line[j];
          at[k * stride] = c;
        }
      }
  }
  return data;
}

std::vector<ProductDomain> BernsteinProduct::subdivide(const ProductDomain& domain) const {
  std::vector<ProductDomain> out{ProductDomain{}};
  for (std::size_t f = 0; f < factors_.size(); ++f) {
    std::vector<ProductDomain> next;
    for (const Simplex& child : children(domain.vertices[f], factors_[f].shape.dim))
      for (ProductDomain d : out) {
        d.vertices.push_back(child);
        next.push_back(std::move(d));
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace geomesh
