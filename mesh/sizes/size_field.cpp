// SizeFields: reading Field definitions, their options and defaults, cycles, and evaluation.
#include "mesh/sizes/size_field.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "mesh/sizes/math_expression.h"
#include "mesh/sizes/point_cloud.h"

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;
constexpr int kMaxDepth = 64;  // deeper field references are taken for a cycle

using Slot = SizeFields::Slot;

constexpr const char* kSlotNames[SizeFields::kSlotCount] = {
    "VIn",     "VOut",    "XMin",    "XMax",    "YMin",    "YMax",    "ZMin",
    "ZMax",    "Thickness", "Radius", "XCenter", "YCenter", "ZCenter", "XAxis",
    "YAxis",   "ZAxis",   "Sampling", "InField", "SizeMin", "SizeMax", "DistMin",
    "DistMax", "Sigmoid", "StopAtDistMax", "IncludeBoundary"};

struct Default {
  Slot slot;
  double value;
};

// The numeric options of each type, with their default values.
std::vector<Default> numericOptions(SizeFields::Type t) {
  using T = SizeFields::Type;
  using S = Slot;
  switch (t) {
    case T::Constant:
      return {{S::VIn, kUnbounded}, {S::VOut, kUnbounded}, {S::IncludeBoundary, 1}};
    case T::Box:
      return {{S::VIn, kUnbounded}, {S::VOut, kUnbounded}, {S::XMin, 0}, {S::XMax, 0},
              {S::YMin, 0},         {S::YMax, 0},          {S::ZMin, 0}, {S::ZMax, 0},
              {S::Thickness, 0}};
    case T::Ball:
      return {{S::VIn, kUnbounded}, {S::VOut, kUnbounded}, {S::Radius, 0}, {S::Thickness, 0},
              {S::XCenter, 0},      {S::YCenter, 0},       {S::ZCenter, 0}};
    case T::Cylinder:
      return {{S::VIn, kUnbounded}, {S::VOut, kUnbounded}, {S::Radius, 0},  {S::XAxis, 0},
              {S::YAxis, 0},        {S::ZAxis, 1},         {S::XCenter, 0}, {S::YCenter, 0},
              {S::ZCenter, 0}};
    case T::Distance: return {{S::Sampling, 20}};
    case T::Threshold:
      return {{S::InField, 0}, {S::SizeMin, 0.1}, {S::SizeMax, 1},       {S::DistMin, 1},
              {S::DistMax, 10}, {S::Sigmoid, 0},  {S::StopAtDistMax, 0}};
    case T::Restrict: return {{S::InField, 0}, {S::IncludeBoundary, 1}};
    case T::MathEval:
    case T::Min:
    case T::Max: return {};
  }
  return {};
}

bool typeNamed(const std::string& name, SizeFields::Type& type) {
  using T = SizeFields::Type;
  static const std::pair<const char*, T> kTypes[] = {
      {"Constant", T::Constant}, {"Box", T::Box},         {"Ball", T::Ball},
      {"Cylinder", T::Cylinder}, {"Distance", T::Distance}, {"Attractor", T::Distance},
      {"Threshold", T::Threshold}, {"MathEval", T::MathEval}, {"Min", T::Min},
      {"Max", T::Max},           {"Restrict", T::Restrict}};
  for (const auto& entry : kTypes)
    if (name == entry.first) return type = entry.second, true;
  return false;
}

std::string canonicalOption(const std::string& name) {
  static const std::pair<const char*, const char*> kAliases[] = {
      {"NodesList", "PointsList"},   {"EdgesList", "CurvesList"},
      {"FacesList", "SurfacesList"}, {"RegionsList", "VolumesList"},
      {"NNodesByEdge", "Sampling"},  {"NumPointsPerCurve", "Sampling"},
      {"IField", "InField"},         {"LcMin", "SizeMin"},
      {"LcMax", "SizeMax"}};
  for (const auto& alias : kAliases)
    if (name == alias.first) return alias.second;
  return name;
}

int listDimension(const std::string& name) {
  if (name == "PointsList") return 0;
  if (name == "CurvesList") return 1;
  if (name == "SurfacesList") return 2;
  if (name == "VolumesList") return 3;
  return -1;
}

bool takesEntities(SizeFields::Type t) {
  using T = SizeFields::Type;
  return t == T::Distance || t == T::Constant || t == T::Restrict;
}

// Points a Distance field measures from: its points, and `sampling` points evenly spaced in
// parameter on each curve (sampling x sampling on each surface).
std::vector<Vec3> distanceSamples(const Model& model, const std::vector<EntityId>& entities,
                                  int sampling) {
  std::vector<Vec3> samples;
  const int n = std::max(sampling, 2);
  for (EntityId e : entities) {
    if (e.dim == 0) {
      if (const ModelPoint* p = model.point(e.tag)) samples.push_back(p->xyz);
    } else if (e.dim == 1) {
      const ModelCurve* c = model.curve(e.tag);
      if (!c || !c->geometry) continue;
      const Interval r = c->geometry->range();
      for (int k = 0; k < n; ++k)
        samples.push_back(c->geometry->point(r.min + (r.max - r.min) * k / (n - 1)));
    } else if (e.dim == 2) {
      const ModelSurface* s = model.surface(e.tag);
      if (!s || !s->geometry) continue;
      const ParamBox box = s->geometry->bounds();
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          const double u = box.u.min + (box.u.max - box.u.min) * i / (n - 1);
          const double v = box.v.min + (box.v.max - box.v.min) * j / (n - 1);
          samples.push_back(s->geometry->point({u, v}));
        }
    }
  }
  return samples;
}

// Reads one definition; unknown options are reported.
SizeFields::Field compile(const Model& model, int tag, const SizeFieldDefinition& def,
                          SizeFields::Type type, MessageSink& log) {
  SizeFields::Field f;
  f.type = type;
  std::vector<std::uint8_t> valid(SizeFields::kSlotCount, 0);
  for (const Default& d : numericOptions(type)) {
    f.slots[static_cast<std::size_t>(d.slot)] = d.value;
    valid[static_cast<std::size_t>(d.slot)] = 1;
  }
  auto slotNamed = [&](const std::string& name) -> int {
    for (int k = 0; k < SizeFields::kSlotCount; ++k)
      if (valid[k] && name == kSlotNames[k]) return k;
    return -1;
  };
  const std::string field = "Field[" + std::to_string(tag) + "]";
  for (const auto& [rawName, values] : def.numbers) {
    const std::string name = canonicalOption(rawName);
    const int dim = listDimension(name);
    if (dim >= 0 && takesEntities(type)) {
      for (double v : values) f.entities.push_back({dim, static_cast<int>(std::lround(v))});
    } else if (name == "FieldsList" && (type == SizeFields::Type::Min ||
                                        type == SizeFields::Type::Max)) {
      for (double v : values) f.fieldsList.push_back(static_cast<int>(std::lround(v)));
    } else if (const int slot = slotNamed(name); slot >= 0 && values.size() == 1) {
      f.slots[static_cast<std::size_t>(slot)] = values.front();
    } else {
      log.warning(field + "." + rawName + " is not an option of this field type; ignored");
    }
  }
  for (const auto& [name, text] : def.strings) {
    if (type == SizeFields::Type::MathEval && name == "F") {
      try {
        f.expression = std::make_unique<MathExpression>(text);
      } catch (const ExpressionError& e) {
        throw ExpressionError(field + ".F: " + e.what());
      }
    }
    else
      log.warning(field + "." + name + " is not an option of this field type; ignored");
  }
  if (type == SizeFields::Type::MathEval && !f.expression)
    f.expression = std::make_unique<MathExpression>("F2 + Sin(z)");
  if (type == SizeFields::Type::Distance)
    f.samples = std::make_unique<PointCloud>(distanceSamples(
        model, f.entities, static_cast<int>(std::lround(f.number(Slot::Sampling)))));
  return f;
}

double boxDistance(Vec3 p, Vec3 lo, Vec3 hi) {
  const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
  const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
  const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

// VIn inside (distance 0), VOut beyond `thickness`, linear in between.
double transition(double distanceOutside, double thickness, double vIn, double vOut) {
  if (distanceOutside <= 0) return vIn;
  if (thickness <= 0 || distanceOutside >= thickness) return vOut;
  const double f = distanceOutside / thickness;
  return vIn + f * (vOut - vIn);
}

double threshold(const SizeFields::Field& f, double d) {
  const double dMin = f.number(Slot::DistMin), dMax = f.number(Slot::DistMax);
  const double sMin = f.number(Slot::SizeMin), sMax = f.number(Slot::SizeMax);
  if (d <= dMin) return sMin;
  if (d >= dMax) return f.number(Slot::StopAtDistMax) != 0 ? kUnbounded : sMax;
  const double r = (d - dMin) / (dMax - dMin);
  if (f.number(Slot::Sigmoid) != 0) {
    const double s = 1 / (1 + std::exp(-12 * (r - 0.5)));
    return sMin + s * (sMax - sMin);
  }
  return sMin + r * (sMax - sMin);
}

// The fields a field reads.
std::vector<int> dependencies(const SizeFields::Field& f) {
  using T = SizeFields::Type;
  if (f.type == T::Threshold || f.type == T::Restrict)
    return {static_cast<int>(std::lround(f.number(Slot::InField)))};
  if (f.type == T::Min || f.type == T::Max) return f.fieldsList;
  if (f.type == T::MathEval) return f.expression->fieldsUsed();
  return {};
}

// Tags of the fields that read themselves, directly or not (depth-first search, colours:
// 0 unseen, 1 on the stack, 2 done).
std::vector<int> fieldsInCycles(const std::map<int, SizeFields::Field>& fields) {
  std::map<int, int> colour;
  std::vector<int> cyclic;
  std::vector<int> stack;
  auto visit = [&](auto&& self, int tag) -> void {
    const auto it = fields.find(tag);
    if (it == fields.end()) return;
    int& c = colour[tag];
    if (c == 1) {
      const auto from = std::find(stack.begin(), stack.end(), tag);
      cyclic.insert(cyclic.end(), from, stack.end());
      return;
    }
    if (c == 2) return;
    c = 1;
    stack.push_back(tag);
    for (int next : dependencies(it->second)) self(self, next);
    stack.pop_back();
    colour[tag] = 2;
  };
  for (const auto& entry : fields) visit(visit, entry.first);
  std::sort(cyclic.begin(), cyclic.end());
  cyclic.erase(std::unique(cyclic.begin(), cyclic.end()), cyclic.end());
  return cyclic;
}

}  // namespace



SizeFields::SizeFields(const Model& model, MessageSink& log) : model_(&model) {
  const MeshConstraints& c = model.meshConstraints();
  for (const auto& [tag, def] : c.sizeFields) {
    Type type;
    if (!typeNamed(def.type, type)) {
      log.warning("Field[" + std::to_string(tag) + "] = " + def.type +
                  " is not a supported field type; it reads as 1e22");
      continue;
    }
    fields_.emplace(tag, compile(model, tag, def, type, log));
  }
  for (int tag : fieldsInCycles(fields_)) {
    log.warning("Field[" + std::to_string(tag) + "] depends on itself; it reads as 1e22");
    fields_.erase(tag);
  }
  background_ = c.backgroundField;
  if (background_ != 0 && !fields_.contains(background_))
    log.warning("Background Field = " + std::to_string(background_) + " is not defined; ignored");
}

SizeFields::~SizeFields() = default;
SizeFields::SizeFields(SizeFields&&) noexcept = default;
SizeFields& SizeFields::operator=(SizeFields&&) noexcept = default;

void SizeFields::evaluate(std::span<const Vec3> points, EntityId where,
                          std::span<double> sizes) const {
  for (std::size_t k = 0; k < points.size(); ++k) sizes[k] = at(points[k], where);
}

double SizeFields::at(Vec3 point, EntityId where) const {
  return hasBackground() ? value(background_, point, where) : kUnbounded;
}

double SizeFields::value(int tag, Vec3 point, EntityId where) const {
  return valueAtDepth(tag, point, where, 0);
}

double SizeFields::valueAtDepth(int tag, Vec3 p, EntityId where, int depth) const {
  const auto it = fields_.find(tag);
  if (it == fields_.end() || depth > kMaxDepth) return kUnbounded;
  return evaluateField(it->second, p, where, depth + 1);
}

bool SizeFields::inEntities(const std::vector<EntityId>& list, EntityId where,
                            bool withBoundary) const {
  for (EntityId e : list) {
    if (e == where) return true;
    if (!withBoundary || where.dim >= e.dim) continue;
    // Is `where` in the closure of e? Walk e's boundary downwards.
    std::vector<EntityId> frontier{e};
    while (!frontier.empty() && frontier.front().dim > where.dim) {
      std::vector<EntityId> next;
      for (EntityId f : frontier)
        for (int b : model_->boundary(f)) next.push_back({f.dim - 1, std::abs(b)});
      frontier = std::move(next);
    }
    if (std::find(frontier.begin(), frontier.end(), where) != frontier.end()) return true;
  }
  return false;
}

double SizeFields::evaluateField(const Field& f, Vec3 p, EntityId where, int depth) const {
  switch (f.type) {
    case Type::Constant:
      return inEntities(f.entities, where, f.number(Slot::IncludeBoundary) != 0)
                 ? f.number(Slot::VIn)
                 : f.number(Slot::VOut);
    case Type::Restrict:
      return inEntities(f.entities, where, f.number(Slot::IncludeBoundary) != 0)
                 ? valueAtDepth(static_cast<int>(f.number(Slot::InField)), p, where, depth)
                 : kUnbounded;
    case Type::Box: {
      const Vec3 lo{f.number(Slot::XMin), f.number(Slot::YMin), f.number(Slot::ZMin)};
      const Vec3 hi{f.number(Slot::XMax), f.number(Slot::YMax), f.number(Slot::ZMax)};
      return transition(boxDistance(p, lo, hi), f.number(Slot::Thickness), f.number(Slot::VIn),
                        f.number(Slot::VOut));
    }
    case Type::Ball: {
      const Vec3 c{f.number(Slot::XCenter), f.number(Slot::YCenter), f.number(Slot::ZCenter)};
      return transition(distance(p, c) - f.number(Slot::Radius), f.number(Slot::Thickness),
                        f.number(Slot::VIn), f.number(Slot::VOut));
    }
    case Type::Cylinder: {
      const Vec3 c{f.number(Slot::XCenter), f.number(Slot::YCenter), f.number(Slot::ZCenter)};
      const Vec3 axis{f.number(Slot::XAxis), f.number(Slot::YAxis), f.number(Slot::ZAxis)};
      const double length = norm(axis);
      if (!(length > 0)) return f.number(Slot::VOut);
      const Vec3 d = p - c;
      const double along = dot(d, axis) / length;
      const double radial = norm(d - (along / length) * axis);
      const bool inside = std::abs(along) <= length && radial <= f.number(Slot::Radius);
      return inside ? f.number(Slot::VIn) : f.number(Slot::VOut);
    }
    case Type::Distance: return f.samples->distanceTo(p);
    case Type::Threshold:
      return threshold(f, valueAtDepth(static_cast<int>(f.number(Slot::InField)), p, where, depth));
    case Type::MathEval: {
      const std::vector<int>& used = f.expression->fieldsUsed();
      double values[16];
      std::vector<double> many;
      double* v = values;
      if (used.size() > 16) many.resize(used.size()), v = many.data();
      for (std::size_t k = 0; k < used.size(); ++k) v[k] = valueAtDepth(used[k], p, where, depth);
      return f.expression->evaluate(p.x, p.y, p.z, {v, used.size()});
    }
    case Type::Min:
    case Type::Max: {
      double result = f.type == Type::Min ? kUnbounded : 0;
      bool any = false;
      for (int tag : f.fieldsList) {
        const double x = valueAtDepth(tag, p, where, depth);
        result = f.type == Type::Min ? std::min(result, x) : (any ? std::max(result, x) : x);
        any = true;
      }
      return any ? result : kUnbounded;
    }
  }
  return kUnbounded;
}

}  // namespace geomesh
