// Combining views: elements joined, or data stacked as time steps.
#include "mesh/views/view_combine.h"

#include <algorithm>
#include <map>
#include <string>
#include <vector>

namespace geomesh::post {

namespace {

// The indices of the views in each group, groups in the order of their first view.
std::vector<std::vector<std::size_t>> groupsOf(const ViewStore& views, CombineGroups groups) {
  std::vector<std::vector<std::size_t>> result;
  std::map<std::string, std::size_t> byName;
  for (std::size_t k = 0; k < views.size(); ++k) {
    if (groups == CombineGroups::All) {
      if (result.empty()) result.emplace_back();
      result.front().push_back(k);
      continue;
    }
    auto [it, added] = byName.emplace(views.at(k).name, result.size());
    if (added) result.emplace_back();
    result[it->second].push_back(k);
  }
  return result;
}

// Removes the views at `indices` (any order) from the store.
void removeAll(ViewStore& views, std::vector<std::size_t> indices) {
  std::sort(indices.begin(), indices.end());
  for (auto it = indices.rbegin(); it != indices.rend(); ++it) views.remove(*it);
}

bool sameSteps(const View& a, const View& b) {
  return a.stepCount() == b.stepCount() || a.elementCount() == 0 || b.elementCount() == 0;
}

void appendElements(View& into, const View& from) {
  for (const ElementList& list : from.lists) {
    ElementList& target = into.list(list.shape, list.kind, list.order);
    if (target.size() == 0) {
      target.nodesPerElement = list.nodesPerElement;
      target.steps = list.steps;
    }
    target.coordinates.insert(target.coordinates.end(), list.coordinates.begin(),
                              list.coordinates.end());
    target.values.insert(target.values.end(), list.values.begin(), list.values.end());
  }
  into.texts.insert(into.texts.end(), from.texts.begin(), from.texts.end());
  into.meshData.reset();
}

// Whether `b` holds the same element lists as `a` (shapes, kinds, counts, coordinates).
bool sameElements(const View& a, const View& b) {
  if (a.lists.size() != b.lists.size()) return false;
  for (std::size_t k = 0; k < a.lists.size(); ++k) {
    const ElementList& x = a.lists[k];
    const ElementList& y = b.lists[k];
    if (x.shape != y.shape || x.kind != y.kind || x.order != y.order ||
        x.nodesPerElement != y.nodesPerElement || x.coordinates != y.coordinates)
      return false;
  }
  return true;
}

// `into`'s lists take `from`'s steps after their own.
void appendSteps(View& into, const View& from) {
  for (std::size_t k = 0; k < into.lists.size(); ++k) {
    ElementList& x = into.lists[k];
    const ElementList& y = from.lists[k];
    const std::size_t perX = x.valuesPerElement(), perY = y.valuesPerElement();
    std::vector<double> values;
    values.reserve(x.values.size() + y.values.size());
    for (std::size_t e = 0; e < x.size(); ++e) {
      values.insert(values.end(), x.values.begin() + std::ptrdiff_t(e * perX),
                    x.values.begin() + std::ptrdiff_t((e + 1) * perX));
      values.insert(values.end(), y.values.begin() + std::ptrdiff_t(e * perY),
                    y.values.begin() + std::ptrdiff_t((e + 1) * perY));
    }
    x.values = std::move(values);
    x.steps += y.steps;
  }
  // Times: each view's own, or its step numbers where it gave none.
  if (!into.times.empty() || !from.times.empty()) {
    const int own = into.stepCount() - from.stepCount();
    for (int s = int(into.times.size()); s < own; ++s) into.times.push_back(s);
    into.times.resize(std::size_t(own));
    for (int s = 0; s < from.stepCount(); ++s)
      into.times.push_back(std::size_t(s) < from.times.size() ? from.times[std::size_t(s)]
                                                              : double(own + s));
  }
  into.meshData.reset();
}

}  // namespace

int combineElements(ViewStore& views, CombineGroups groups) {
  std::vector<std::size_t> merged;
  for (const auto& group : groupsOf(views, groups)) {
    View& first = views.at(group.front());
    bool fits = true;
    for (std::size_t k = 1; k < group.size(); ++k) fits = fits && sameSteps(first, views.at(group[k]));
    if (!fits) continue;
    for (std::size_t k = 1; k < group.size(); ++k) {
      appendElements(first, views.at(group[k]));
      merged.push_back(group[k]);
    }
  }
  removeAll(views, merged);
  return static_cast<int>(merged.size());
}

int combineTimeSteps(ViewStore& views, CombineGroups groups) {
  std::vector<std::size_t> merged;
  for (const auto& group : groupsOf(views, groups)) {
    View& first = views.at(group.front());
    bool fits = true;
    for (std::size_t k = 1; k < group.size(); ++k)
      fits = fits && sameElements(first, views.at(group[k]));
    if (!fits) continue;
    for (std::size_t k = 1; k < group.size(); ++k) {
      appendSteps(first, views.at(group[k]));
      merged.push_back(group[k]);
    }
  }
  removeAll(views, merged);
  return static_cast<int>(merged.size());
}

}  // namespace geomesh::post
