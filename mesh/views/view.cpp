// Views: element lists, the figures scripts read from a view, and the store of a session.
#include "mesh/views/view.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geomesh::post {

int cornerCount(ElementShape shape) {
  static constexpr int kCorners[kShapeCount] = {1, 2, 3, 4, 4, 8, 6, 5};
  return kCorners[static_cast<int>(shape)];
}

int shapeDimension(ElementShape shape) {
  static constexpr int kDimension[kShapeCount] = {0, 1, 2, 2, 3, 3, 3, 3};
  return kDimension[static_cast<int>(shape)];
}

char shapeLetter(ElementShape shape) { return "PLTQSHIY"[static_cast<int>(shape)]; }

std::optional<ListType> listTypeOf(std::string_view name) {
  if (name.size() < 2 || name.size() > 3) return std::nullopt;
  constexpr std::string_view kinds = "SVT", shapes = "PLTQSHIY";
  const auto kind = kinds.find(name[0]), shape = shapes.find(name[1]);
  if (kind == std::string_view::npos || shape == std::string_view::npos) return std::nullopt;
  if (name.size() == 3 && (name[2] != '2' || name[1] == 'P')) return std::nullopt;
  return ListType{static_cast<FieldKind>(kind), static_cast<ElementShape>(shape),
                  name.size() == 3 ? 2 : 1};
}

int componentCount(FieldKind kind) {
  switch (kind) {
    case FieldKind::Scalar: return 1;
    case FieldKind::Vector: return 3;
    case FieldKind::Tensor: return 9;
  }
  return 1;
}

char kindLetter(FieldKind kind) { return "SVT"[static_cast<int>(kind)]; }

int ElementList::components() const { return componentCount(kind); }

std::size_t ElementList::size() const {
  return nodesPerElement > 0 ? coordinates.size() / (3 * std::size_t(nodesPerElement)) : 0;
}

std::size_t ElementList::valuesPerElement() const {
  return std::size_t(steps) * std::size_t(nodesPerElement) * std::size_t(components());
}

double ElementList::value(std::size_t element, int step, int node, int component) const {
  return values[element * valuesPerElement() +
                (std::size_t(step) * std::size_t(nodesPerElement) + std::size_t(node)) *
                    std::size_t(components()) +
                std::size_t(component)];
}

ElementList& View::list(ElementShape shape, FieldKind kind, int order) {
  for (ElementList& l : lists)
    if (l.shape == shape && l.kind == kind && l.order == order) return l;
  ElementList& l = lists.emplace_back();
  l.shape = shape;
  l.kind = kind;
  l.order = order;
  l.nodesPerElement = cornerCount(shape);
  return l;
}

int View::stepCount() const {
  int steps = 0;
  for (const ElementList& l : lists)
    if (l.size() > 0) steps = std::max(steps, l.steps);
  for (const TextItem& t : texts) steps = std::max(steps, int(t.text.size()));
  return steps;
}

namespace {

// The smallest and largest value (norm for vectors and tensors) over every list and step.
std::pair<double, double> valueRange(const View& view) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (const ElementList& l : view.lists) {
    const int c = l.components();
    for (std::size_t k = 0; k + std::size_t(c) <= l.values.size(); k += std::size_t(c)) {
      double v = l.values[k];
      if (c > 1) {
        double sum = 0;
        for (int i = 0; i < c; ++i) sum += l.values[k + std::size_t(i)] * l.values[k + std::size_t(i)];
        v = std::sqrt(sum);
      }
      low = std::min(low, v);
      high = std::max(high, v);
    }
  }
  if (low > high) return {0, 0};
  return {low, high};
}

}  // namespace

double View::minimum() const { return valueRange(*this).first; }
double View::maximum() const { return valueRange(*this).second; }

bool View::empty() const { return elementCount() == 0 && texts.empty(); }

std::size_t View::elementCount() const {
  std::size_t n = 0;
  for (const ElementList& l : lists) n += l.size();
  return n;
}

View& ViewStore::add(std::string name) {
  auto view = std::make_unique<View>();
  view->tag = nextTag_++;
  view->name = std::move(name);
  views_.push_back(std::move(view));
  return *views_.back();
}

View* ViewStore::withTag(int tag) {
  const int index = indexOfTag(tag);
  return index < 0 ? nullptr : views_[std::size_t(index)].get();
}

const View* ViewStore::withTag(int tag) const {
  const int index = indexOfTag(tag);
  return index < 0 ? nullptr : views_[std::size_t(index)].get();
}

int ViewStore::indexOfTag(int tag) const {
  for (std::size_t k = 0; k < views_.size(); ++k)
    if (views_[k]->tag == tag) return int(k);
  return -1;
}

void ViewStore::remove(std::size_t index) {
  if (index >= views_.size()) throw std::out_of_range("no view at this index");
  views_.erase(views_.begin() + std::ptrdiff_t(index));
}

void ViewStore::clear() { views_.clear(); }

}  // namespace geomesh::post
