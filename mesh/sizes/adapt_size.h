// AdaptSize: the Adapt field, new mesh sizes from per-element error estimates in a view.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "kernel/vec3.h"
#include "mesh/views/view.h"
#include "mesh/views/view_probe.h"

namespace geomesh {

// Field[n] = Adapt: sizes for a new mesh from error estimates e_i on the elements K_i of the
// current mesh (a view: one value per element, or nodal values whose mean is taken; only the
// elements of dimension d count).
//
// Element size. h_i is the edge of the equilateral simplex of the same measure:
// |K| = c_d h^d with c_1 = 1, c_2 = sqrt(3)/4, c_3 = sqrt(2)/12. A mesh of size h over a
// measure |K| then has |K| / (c_d h^d) elements (quadrangles and hexahedra count as the
// simplices a simplex mesher would put there).
//
// Error model. An element of size h with pointwise error ~ h^k (k = Order) over a measure
// ~ h^d contributes e = C h^p, p = k + d/2, so C_i = e_i / h_i^p, and the total error is
// E = sqrt(sum e_i^2).
//
// Optimal sizes. New size h'_i over K_i: n_i = |K_i| / (c_d h'_i^d) new elements, each of
// error C_i h'_i^p, so E'^2 = sum_i n_i C_i^2 h'_i^(2p) = sum_i (|K_i|/c_d) C_i^2 h'_i^(2k)
// and N' = sum_i |K_i| / (c_d h'_i^d). Minimising E'^2 at fixed N' (Lagrange:
// 2k |K_i| C_i^2 h'^(2k-1) = lambda d |K_i| h'^(-d-1)) gives h'_i^(2k+d) ~ C_i^-2, that is
// h'_i = mu C_i^(-1/p): every new element has the same error mu^p (equidistribution). With
// S = sum_i |K_i| C_i^(d/p):
//  - TargetElements N: N' = S / (c_d mu^d) = N gives mu = (S / (c_d N))^(1/d);
//  - TargetError E: N' (mu^p)^2 = E^2 gives mu^(2k) = c_d E^2 / S.
// The sizes are then clamped to [SizeMin, SizeMax] (the targets hold before clamping). An
// element with no error (C_i = 0) asks for SizeMax.
//
// The field at a point: each node of the view (nodes merged by equal coordinates) takes the
// geometric mean of the new sizes of the elements around it, and the field interpolates these
// nodal sizes linearly in the element holding the point (smoother than a piecewise constant
// size, which makes the mesher jump at every old edge); outside the view, the size at the
// nearest node.
struct AdaptOptions {
  int order = 2;              // Order: k
  int dimension = -1;         // Dimension: d; -1, the highest dimension of the view's elements
  double targetElements = 0;  // TargetElements: N (0: off)
  double targetError = 0;     // TargetError: E (0: off)
  double sizeMin = 0;
  double sizeMax = 1e22;
};

// The optimisation's result on the view's elements of dimension `dimension`, in the order of
// the view's lists (degenerate elements, of zero measure, are left out).
struct AdaptedSizes {
  struct Source {
    std::size_t list = 0, element = 0;  // where element i is in the view
  };
  int dimension = 0;
  std::vector<Source> sources;
  double unitMeasure = 1;        // c_d
  std::vector<double> measures;  // |K_i|
  std::vector<double> errors;    // e_i
  std::vector<double> sizes;     // h_i
  std::vector<double> newSizes;  // h'_i, clamped
  double predictedElements = 0;  // N' = sum |K_i| / (c_d h'_i^d), before clamping
  double predictedError = 0;     // sqrt(sum (|K_i|/c_d) C_i^2 h'_i^(2k)), before clamping
};

// The new sizes; nullopt with the reason in `why` when the options or the view do not allow
// them (neither or both targets, Order <= 0, no element of the dimension).
std::optional<AdaptedSizes> adaptSizes(const post::View& view, const AdaptOptions& options,
                                       std::string& why);

// The Adapt field over a view, built once; at() is const and thread-safe.
class AdaptSize {
 public:
  AdaptSize(const post::View& view, const AdaptedSizes& sizes, const AdaptOptions& options);
  double at(Vec3 p) const;

 private:
  static post::View nodalSizes(const post::View& view, const AdaptedSizes& sizes);
  post::ViewProbe probe_;
  double sizeMin_ = 0, sizeMax_ = 1e22;
};

}  // namespace geomesh
