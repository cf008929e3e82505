// Setting options and parameters of a session, as the command line and a binding do.
#pragma once

#include <string>

#include "api/session.h"

namespace geomesh::api {

// -setnumber / -setstring: the option of that name if there is one, else a parameter that the
// script reads as a variable and that overrides its DefineConstant / DefineNumber /
// DefineString of the same name. (Options alone are set on session.options().)
void setNumber(Session& session, const std::string& name, double value);
void setString(Session& session, const std::string& name, const std::string& value);

}  // namespace geomesh::api
