// ShapeFunctions: the Lagrange basis of an element type, built from its reference nodes.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "mesh/core/element_type.h"

namespace geomesh {

// Exponents (a, b, c) of the monomial x^a y^b z^c in reference coordinates.
using Monomial = std::array<int, 3>;

// The shape functions of one element type: function i is 1 at reference node i (MSH order)
// and 0 at the others. They span a polynomial space per family: P_p on lines, triangles and
// tetrahedra; Q_p (tensor) on quadrangles and hexahedra; P_p(triangle) x P_p(line) on prisms;
// x^a y^b z^c with a, b <= p - c on pyramids. A serendipity type takes, from its family's
// complete space, the monomials of lowest degree first, skipping each one that adds nothing
// on its nodes, until it has one per node.
class ShapeFunctions {
 public:
  // Throws std::logic_error when the space is not unisolvent on the nodes.
  explicit ShapeFunctions(ElementType type);

  ElementType type() const { return type_; }
  int size() const { return static_cast<int>(monomials_.size()); }
  std::span<const Monomial> monomials() const { return monomials_; }

  // One value per node into `out` (at least size() long).
  void values(const std::array<double, 3>& xi, std::span<double> out) const;
  // One gradient (d/dx, d/dy, d/dz in reference coordinates) per node into `out`.
  void gradients(const std::array<double, 3>& xi, std::span<std::array<double, 3>> out) const;

 private:
  ElementType type_;
  std::vector<Monomial> monomials_;
  // Inverse of the Vandermonde matrix V[node][monomial], row-major: shape function i is
  // sum over m of inverse_[m * n + i] x^m.
  std::vector<double> inverse_;
};

// The shape functions of a type, built on first use and kept; safe from several threads.
const ShapeFunctions& shapeFunctions(ElementType type);

}  // namespace geomesh
