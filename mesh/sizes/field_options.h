// Field option tables: each field type's name, numeric options with defaults, strings, lists.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "mesh/sizes/size_field.h"

namespace geomesh {

// The reference's name of a field type (several names may give one type: Attractor is
// Distance); nullopt for a name that is not a field type.
std::optional<SizeFields::Type> fieldTypeNamed(const std::string& name);

// The name an option is stored under, from any of its older names (NodesList, lMinTangent,
// R1_inner, ...).
std::string canonicalFieldOption(const std::string& name);

// The option name of a numeric slot.
const char* slotName(SizeFields::Slot slot);

struct SlotDefault {
  SizeFields::Slot slot;
  double value;
};
// The numeric options of a type, with their defaults.
std::vector<SlotDefault> numericOptions(SizeFields::Type type);

// The string options of a type, with their defaults.
struct StringOption {
  const char* name;
  const char* value;
};
std::vector<StringOption> stringOptions(SizeFields::Type type);

// The entity dimension a list option names (PointsList 0 ... VolumesList 3), or -1.
int listDimension(const std::string& name);
// Whether a type takes a list of entities of that dimension.
bool takesEntityList(SizeFields::Type type, int dim);
// Whether a type takes FieldsList.
bool takesFieldsList(SizeFields::Type type);

}  // namespace geomesh
