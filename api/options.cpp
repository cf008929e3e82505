// Options or parameters, by name.
#include "api/options.h"

namespace geomesh::api {

void setNumber(Session& session, const std::string& name, double value) {
  if (session.options().hasNumber(name))
    session.options().setNumber(name, value);
  else
    session.numberOverrides()[name] = value;
}

void setString(Session& session, const std::string& name, const std::string& value) {
  if (session.options().hasString(name))
    session.options().setString(name, value);
  else
    session.stringOverrides()[name] = value;
}

}  // namespace geomesh::api
