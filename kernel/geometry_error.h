#pragma once

#include <stdexcept>
#include <string>

namespace geomesh {

// A geometry construction that cannot be carried out (undefined entity, open loop, ...). The
// message names the entity; the interpreter adds the script location.
class GeometryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace geomesh
