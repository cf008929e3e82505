// ViewSize: sizes and metrics interpolated in a view, with the PostView field's options.
#include "mesh/sizes/view_size.h"

#include <cmath>

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;

bool holdsTensors(const post::View& view) {
  for (const post::ElementList& l : view.lists)
    if (l.kind == post::FieldKind::Tensor && l.size() > 0) return true;
  return false;
}

// The size the components found at a point ask for: the value, the norm of a vector, the
// smallest size of a tensor's metric.
double sizeOf(const std::array<double, 9>& values, int count) {
  if (count == 9) return smallestSize(symmetrised(values));
  if (count == 1) return values[0];
  double sum = 0;
  for (int k = 0; k < count; ++k) sum += values[std::size_t(k)] * values[std::size_t(k)];
  return std::sqrt(sum);
}

}  // namespace

ViewSize::ViewSize(const post::View& view, Options options)
    : probe_(view), options_(options), tensors_(holdsTensors(view)) {}

double ViewSize::size(Vec3 p) const {
  int count = 0;
  std::optional<std::array<double, 9>> values = probe_.components(p, &count);
  if (!values && options_.useClosest) values = probe_.nearestComponents(p, &count);
  if (!values) return kUnbounded;
  const double h = sizeOf(*values, count);
  if (options_.cropNegative && !(h > 0)) return kUnbounded;
  return h;
}

std::optional<SymmetricTensor> ViewSize::tensor(Vec3 p) const {
  if (!tensors_) return std::nullopt;
  int count = 0;
  std::optional<std::array<double, 9>> values = probe_.components(p, &count);
  if (!values && options_.useClosest) values = probe_.nearestComponents(p, &count);
  if (!values || count != 9) return std::nullopt;
  return symmetrised(*values);
}

const post::View* viewNamed(const post::ViewStore* views, int index, int tag) {
  if (!views) return nullptr;
  if (tag >= 0) return views->withTag(tag);
  if (index < 0 || std::size_t(index) >= views->size()) return nullptr;
  return &views->at(std::size_t(index));
}

}  // namespace geomesh
