// ViewProbe: the values of a view at any point, interpolated in the element that holds it.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "kernel/vec3.h"
#include "mesh/views/view.h"

namespace geomesh::post {

// Finds the element of a view that holds a point (through a bucket grid over the elements'
// bounding boxes) and interpolates its nodal values there with the element's shape
// functions. Points are found within a small tolerance (1e-6 of the view's extent, and in
// the plane of a 2D view's elements even when slightly off it), so a view of triangles in
// z = 0 answers at points of a surface mesh there. Build once, query many times; queries are
// const and may run from several threads.
class ViewProbe {
 public:
  // `dimension` restricts the search to elements of that dimension (-1: the highest
  // dimension present, and lower ones where no element of that dimension holds the point).
  ViewProbe(const View& view, int step = 0, int dimension = -1);
  ~ViewProbe();
  ViewProbe(ViewProbe&&) noexcept;
  ViewProbe& operator=(ViewProbe&&) noexcept;

  // The scalar value (for vector and tensor data: the norm) at a point; nullopt outside.
  std::optional<double> scalar(Vec3 point) const;
  // All components at a point (1, 3 or 9 of them); nullopt outside.
  std::optional<std::array<double, 9>> components(Vec3 point, int* count = nullptr) const;
  // The symmetric tensor at a point (xx, xy, xz, yy, yz, zz), from tensor data; nullopt
  // outside or when the view holds no tensor.
  std::optional<std::array<double, 6>> tensor(Vec3 point) const;
  // The value at the nearest node of the view (for points outside every element).
  std::optional<double> nearestScalar(Vec3 point) const;
  // All components at the nearest node of the view (1, 3 or 9 of them); nullopt if no node.
  std::optional<std::array<double, 9>> nearestComponents(Vec3 point, int* count = nullptr) const;

 private:
  struct Index;
  std::unique_ptr<Index> index_;
};

}  // namespace geomesh::post
