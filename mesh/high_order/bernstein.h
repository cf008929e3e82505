// BernsteinProduct: polynomials on a product of simplices (a line, triangle, tetrahedron,
// quadrangle, hexahedron or prism) from their values at a lattice to Bernstein coefficients,
// and the subdivision of such domains.
#pragma once

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace geomesh {

// One simplex factor of a product domain: its dimension (1..3), the degree of the polynomial
// along it, and the first of the `dim` reference axes it spans.
struct SimplexFactor {
  int dim = 1;
  int degree = 0;
  int axis = 0;
};

// A product of simplices placed in reference coordinates: per factor, its dim + 1 vertices
// (the first `dim` coordinates of each are used).
struct ProductDomain {
  std::vector<std::array<std::array<double, 3>, 4>> vertices;
};

// The Bernstein basis of a product of simplex factors, with the lattice where a polynomial of
// that degree is sampled. Samples and coefficients share one order: the last factor fastest.
// The Bernstein coefficients of a polynomial bound it on its domain (min <= p <= max), and
// they converge to its values as the domain is subdivided.
class BernsteinProduct {
 public:
  explicit BernsteinProduct(std::vector<SimplexFactor> factors);

  std::size_t size() const { return size_; }
  // The reference coordinates of sample s on `domain`.
  std::array<double, 3> point(const ProductDomain& domain, std::size_t s) const;
  // The Bernstein coefficients of the polynomial whose lattice samples are `samples`.
  std::vector<double> coefficients(std::span<const double> samples) const;
  // The 2, 4 or 8 children of each factor's simplex, combined in every way.
  std::vector<ProductDomain> subdivide(const ProductDomain& domain) const;

 private:
  struct Factor {
    SimplexFactor shape;
    std::vector<std::array<double, 4>> barycentric;  // per lattice point
    std::vector<double> toBernstein;                  // row-major, lattice size squared
  };
  std::vector<Factor> factors_;
  std::size_t size_ = 1;
};

}  // namespace geomesh
