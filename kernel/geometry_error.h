// GeometryError: a geometry construction that cannot be carried out, naming the entity.
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

// An operation a geometry factory does not offer (yet): names the operation, as scripts name
// it ("Point", "Box", "Extrude"), and the factory ("Built-in", "OpenCASCADE").
class UnsupportedOperation : public GeometryError {
 public:
  UnsupportedOperation(std::string operation, std::string factory)
      : GeometryError("'" + operation + "' is not supported by the " + factory + " factory"),
        operation_(std::move(operation)),
        factory_(std::move(factory)) {}

  const std::string& operation() const { return operation_; }
  const std::string& factory() const { return factory_; }

 private:
  std::string operation_, factory_;
};

}  // namespace geomesh
