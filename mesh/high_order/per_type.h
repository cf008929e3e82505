// perType: a table built once per element type, on first use, then read without a lock.
#pragma once

#include <array>
#include <memory>
#include <mutex>

#include "mesh/core/element_type.h"

namespace geomesh {

// One slot per MSH type number; `Table` is constructed from the type.
template <class Table>
const Table& perType(ElementType type) {
  constexpr std::size_t kSlots = 256;
  static std::array<std::once_flag, kSlots> once;
  static std::array<std::unique_ptr<Table>, kSlots> built;
  const auto slot = static_cast<std::size_t>(type);
  std::call_once(once[slot], [&] { built[slot] = std::make_unique<Table>(type); });
  return *built[slot];
}

}  // namespace geomesh
