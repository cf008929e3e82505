// ViewSize: mesh sizes and metrics read from a view (PostView fields, Background Mesh View).
#pragma once

#include <optional>

#include "kernel/vec3.h"
#include "mesh/sizes/metric_tensor.h"
#include "mesh/views/view.h"
#include "mesh/views/view_probe.h"

namespace geomesh {

// The sizes a view asks for, as the reference's PostView field reads them:
//  - scalar data: the value interpolated in the element holding the point (vector data: the
//    norm); tensor data: 1/sqrt of the largest eigenvalue of the symmetrised tensor, the
//    smallest size of the metric (the reference's isotropic meshers find no scalar in a
//    tensor view and read 1e22 there; geomesh follows the metric's smallest size, as for
//    MathEvalAniso).
//  - outside every element: with useClosest (UseClosest, default 1) the value at the view's
//    nearest node, else 1e22.
//  - cropNegative (CropNegativeValues, default 1): a value <= 0 reads 1e22. Without it the
//    value is returned as is (the reference then stops on a size <= 0).
// The view is indexed once (time step 0) at construction; queries are const and thread-safe.
class ViewSize {
 public:
  struct Options {
    bool cropNegative = true;
    bool useClosest = true;
  };
  ViewSize(const post::View& view, Options options);

  double size(Vec3 p) const;
  // The symmetrised tensor at p for a tensor view (at the nearest node outside, with
  // useClosest); nullopt for other views or where the view gives nothing.
  std::optional<SymmetricTensor> tensor(Vec3 p) const;
  // Whether the view holds tensors.
  bool anisotropic() const { return tensors_; }

 private:
  post::ViewProbe probe_;
  Options options_;
  bool tensors_ = false;
};

// The view a field names: the one of tag `tag` when tag >= 0, else the one at `index`; null
// when there is none (or no store).
const post::View* viewNamed(const post::ViewStore* views, int index, int tag);

}  // namespace geomesh
