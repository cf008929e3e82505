// SizeFields: reading Field definitions, their options and defaults, cycles, and evaluation.
#include "mesh/sizes/size_field.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <utility>

#include "mesh/sizes/adapt_size.h"
#include "mesh/sizes/automatic_size.h"
#include "mesh/sizes/boundary_extension.h"
#include "mesh/sizes/boundary_layer_field.h"
#include "mesh/sizes/field_options.h"
#include "mesh/sizes/finite_differences.h"
#include "mesh/sizes/math_expression.h"
#include "mesh/sizes/metric_tensor.h"
#include "mesh/sizes/point_cloud.h"
#include "mesh/sizes/view_size.h"

namespace geomesh {
namespace {

constexpr double kUnbounded = 1e22;
constexpr int kMaxDepth = 64;  // deeper field references are taken for a cycle

using Slot = SizeFields::Slot;
using Type = SizeFields::Type;

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

std::vector<int> tagsOfDimension(const std::vector<EntityId>& entities, int dim) {
  std::vector<int> tags;
  for (EntityId e : entities)
    if (e.dim == dim) tags.push_back(e.tag);
  return tags;
}

int rounded(double x) { return static_cast<int>(std::lround(x)); }

// Compiles a formula option; a syntax error names the field and the option.
std::unique_ptr<MathExpression> compileFormula(const std::string& field, const std::string& name,
                                               const std::string& text) {
  try {
    return std::make_unique<MathExpression>(text);
  } catch (const ExpressionError& e) {
    throw ExpressionError(field + "." + name + ": " + e.what());
  }
}

// Reads the string options of a type (formulas, command lines, file names).
void readStrings(SizeFields::Field& f, const std::string& field, const SizeFieldDefinition& def,
                 MessageSink& log) {
  const std::vector<StringOption> options = stringOptions(f.type);
  for (const auto& entry : def.strings) {
    const std::string& name = entry.first;
    if (std::none_of(options.begin(), options.end(),
                     [&](const StringOption& o) { return name == o.name; }))
      log.warning(field + "." + name + " is not an option of this field type; ignored");
  }
  const auto valueOf = [&](const StringOption& o) {
    const auto it = def.strings.find(o.name);
    return it != def.strings.end() ? it->second : std::string(o.value);
  };
  if (f.type == Type::MathEval) {
    f.expression = compileFormula(field, "F", valueOf(options.front()));
  } else if (f.type == Type::MathEvalAniso) {
    for (const StringOption& o : options)
      f.expressions.push_back(compileFormula(field, o.name, valueOf(o)));
  } else if (f.type == Type::Param) {
    const char* coordinates[] = {"x", "y", "z"};
    for (std::size_t k = 0; k < options.size(); ++k) {
      const std::string text = valueOf(options[k]);
      const bool blank = text.find_first_not_of(" \t") == std::string::npos;
      f.expressions.push_back(
          compileFormula(field, options[k].name, blank ? coordinates[k] : text));
    }
  } else if (f.type == Type::ExternalProcess) {
    const std::string command = valueOf(options.front());
    log.warning(field + " = ExternalProcess is refused: geomesh does not run external programs" +
                (command.empty() ? std::string() : " (CommandLine \"" + command + "\")") +
                "; it reads as 1e22");
  } else if (f.type == Type::Automatic && !valueOf(options.front()).empty()) {
    log.warning(field + ".p4estFileToLoad is not followed: geomesh does not read p4est files; "
                        "the sizes are computed from the model");
  }
}

// I/h^2 for a size h; a size <= 0 or not finite asks for nothing.
SymmetricTensor sizeTensor(double h) {
  return isotropicTensor(h > 0 && std::isfinite(h) ? h : kUnbounded);
}

// A PostView field's view, indexed; a missing view is reported and leaves the field unset.
void precomputePostView(SizeFields::Field& f, const std::string& field,
                        const MeshOptions& options, MessageSink& log) {
  const int index = rounded(f.number(Slot::ViewIndex)), tag = rounded(f.number(Slot::ViewTag));
  const post::View* view = viewNamed(options.views, index, tag);
  if (!view) {
    log.warning(field + " = PostView: there is no view " +
                (tag >= 0 ? "of tag " + std::to_string(tag) : "at index " + std::to_string(index)) +
                "; the field reads 1e22");
    return;
  }
  f.view = std::make_unique<ViewSize>(
      *view, ViewSize::Options{f.number(Slot::CropNegativeValues) != 0,
                               f.number(Slot::UseClosest) != 0});
}

// An Adapt field's sizes; a missing view or wrong options are reported (the field reads 1e22).
void precomputeAdapt(SizeFields::Field& f, const std::string& field, const MeshOptions& options,
                     MessageSink& log) {
  const int index = rounded(f.number(Slot::View));
  const post::View* view = viewNamed(options.views, index, -1);
  if (!view) {
    log.warning(field + " = Adapt: there is no view at index " + std::to_string(index) +
                " (option View); the field reads 1e22");
    return;
  }
  AdaptOptions o;
  o.order = rounded(f.number(Slot::Order));
  o.dimension = rounded(f.number(Slot::Dimension));
  o.targetElements = f.number(Slot::TargetElements);
  o.targetError = f.number(Slot::TargetError);
  o.sizeMin = f.number(Slot::SizeMin);
  o.sizeMax = f.number(Slot::SizeMax);
  std::string why;
  const std::optional<AdaptedSizes> sizes = adaptSizes(*view, o, why);
  if (!sizes) {
    log.warning(field + " = Adapt: " + why + "; the field reads 1e22");
    return;
  }
  f.adapt = std::make_unique<AdaptSize>(*view, *sizes, o);
}

// Builds what a type precomputes from the model: sample clouds, boundary edges, sources.
void precompute(SizeFields::Field& f, const std::string& field, const Model& model,
                const MeshOptions& options, MessageSink& log) {
  if (f.type == Type::Distance) {
    f.samples = std::make_unique<PointCloud>(
        distanceSamples(model, f.entities, rounded(f.number(Slot::Sampling))));
  } else if (f.type == Type::AttractorAnisoCurve) {
    f.samples = std::make_unique<PointCloud>(
        distanceSamples(model, f.entities, rounded(f.number(Slot::Sampling))));
  } else if (f.type == Type::Extend) {
    const BoundaryExtension::Law law{f.number(Slot::DistMax), f.number(Slot::Power),
                                     f.number(Slot::SizeMax)};
    f.extension = std::make_unique<BoundaryExtension>(model, tagsOfDimension(f.entities, 1),
                                                      tagsOfDimension(f.entities, 2), law,
                                                      options);
  } else if (f.type == Type::Automatic) {
    if (f.number(Slot::Smoothing) == 0)
      log.warning(field + ".smoothing = 0 is not followed: geomesh always grades the sizes by "
                          "'gradation'");
    AutomaticSize::Options o;
    o.hBulk = f.number(Slot::HBulk);
    o.hMin = f.number(Slot::HMin);
    o.hMax = f.number(Slot::HMax);
    o.gradation = f.number(Slot::Gradation);
    o.features = f.number(Slot::Features) != 0;
    o.pointsPerCircle = rounded(f.number(Slot::PointsPerCircle));
    o.pointsPerGap = rounded(f.number(Slot::PointsPerGap));
    f.automatic = std::make_unique<AutomaticSize>(model, o);
  } else if (f.type == Type::PostView) {
    precomputePostView(f, field, options, log);
  } else if (f.type == Type::Adapt) {
    precomputeAdapt(f, field, options, log);
  } else if (f.type == Type::Gradient) {
    const int kind = rounded(f.number(Slot::Kind));
    if (kind < 0 || kind > 3)
      log.warning(field + ".Kind = " + std::to_string(kind) +
                  " is not a gradient component (0, 1, 2 or 3); the field reads as 1e22");
  }
}

// A BoundaryLayer field: its options, and the distance to its curves for its sizes.
SizeFields::Field compileLayer(const Model& model, int tag, const SizeFieldDefinition& def,
                               MessageSink& log) {
  SizeFields::Field f;
  f.type = Type::BoundaryLayer;
  f.layer = std::make_unique<BoundaryLayerParameters>();
  f.layer->tag = tag;
  readBoundaryLayerOptions(*f.layer, "Field[" + std::to_string(tag) + "]", def, log);
  f.wallDistance = std::make_unique<CurveDistance>(model, f.layer->curves);
  return f;
}

// Reads one definition; unknown options are reported.
SizeFields::Field compile(const Model& model, int tag, const SizeFieldDefinition& def,
                          Type type, const MeshOptions& options, MessageSink& log) {
  if (type == Type::BoundaryLayer) return compileLayer(model, tag, def, log);
  SizeFields::Field f;
  f.type = type;
  std::vector<std::uint8_t> valid(SizeFields::kSlotCount, 0);
  for (const SlotDefault& d : numericOptions(type)) {
    f.slots[static_cast<std::size_t>(d.slot)] = d.value;
    valid[static_cast<std::size_t>(d.slot)] = 1;
  }
  auto slotNamed = [&](const std::string& name) -> int {
    for (int k = 0; k < SizeFields::kSlotCount; ++k)
      if (valid[k] && name == slotName(static_cast<Slot>(k))) return k;
    return -1;
  };
  const std::string field = "Field[" + std::to_string(tag) + "]";
  for (const auto& [rawName, values] : def.numbers) {
    const std::string name = canonicalFieldOption(rawName);
    const int dim = listDimension(name);
    if (dim >= 0 && takesEntityList(type, dim)) {
      for (double v : values) f.entities.push_back({dim, rounded(v)});
    } else if (name == "FieldsList" && takesFieldsList(type)) {
      for (double v : values) f.fieldsList.push_back(rounded(v));
    } else if (const int slot = slotNamed(name); slot >= 0 && values.size() == 1) {
      f.slots[static_cast<std::size_t>(slot)] = values.front();
    } else {
      log.warning(field + "." + rawName + " is not an option of this field type; ignored");
    }
  }
  readStrings(f, field, def, log);
  precompute(f, field, model, options, log);
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

// Sizes interpolated along the axis (u) and across the shell (v) of a Frustum.
double frustum(const SizeFields::Field& f, Vec3 p) {
  const Vec3 p1{f.number(Slot::X1), f.number(Slot::Y1), f.number(Slot::Z1)};
  const Vec3 p2{f.number(Slot::X2), f.number(Slot::Y2), f.number(Slot::Z2)};
  const Vec3 axis = p2 - p1;
  const double length2 = dot(axis, axis);
  if (!(length2 > 0)) return kUnbounded;
  const double u = dot(p - p1, axis) / length2;
  if (!(u >= 0 && u <= 1)) return kUnbounded;
  const double r = norm(p - p1 - u * axis);
  const double inner = (1 - u) * f.number(Slot::InnerR1) + u * f.number(Slot::InnerR2);
  const double outer = (1 - u) * f.number(Slot::OuterR1) + u * f.number(Slot::OuterR2);
  const double v = (r - inner) / (outer - inner);
  if (!(v >= 0 && v <= 1)) return kUnbounded;
  const double vIn = (1 - u) * f.number(Slot::InnerV1) + u * f.number(Slot::InnerV2);
  const double vOut = (1 - u) * f.number(Slot::OuterV1) + u * f.number(Slot::OuterV2);
  return (1 - v) * vIn + v * vOut;
}

// The smaller of the tangent and normal sizes at distance d from the curves.
double anisoCurveSize(const SizeFields::Field& f, double d) {
  const double dMin = f.number(Slot::DistMin), dMax = f.number(Slot::DistMax);
  double w = d <= dMin ? 0 : d >= dMax ? 1 : (d - dMin) / (dMax - dMin);
  if (!std::isfinite(w)) w = 1;
  const double tangent =
      (1 - w) * f.number(Slot::SizeMinTangent) + w * f.number(Slot::SizeMaxTangent);
  const double normal = (1 - w) * f.number(Slot::SizeMinNormal) + w * f.number(Slot::SizeMaxNormal);
  return std::min(tangent, normal);
}

// The fields a field reads.
std::vector<int> dependencies(const SizeFields::Field& f) {
  std::vector<int> tags;
  if (f.type == Type::Min || f.type == Type::Max) return f.fieldsList;
  if (f.type == Type::MathEval) return f.expression->fieldsUsed();
  for (const auto& e : f.expressions)
    tags.insert(tags.end(), e->fieldsUsed().begin(), e->fieldsUsed().end());
  if (const int in = f.inField(); in != 0) tags.push_back(in);
  return tags;
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

int SizeFields::Field::inField() const {
  switch (type) {
    case Type::Threshold:
    case Type::Restrict:
    case Type::Param:
    case Type::Gradient:
    case Type::Curvature:
    case Type::Laplacian:
    case Type::MaxEigenHessian:
    case Type::Mean:
    case Type::Octree: return rounded(number(Slot::InField));
    default: return 0;
  }
}

SizeFields::SizeFields(const Model& model, MessageSink& log, const MeshOptions& options)
    : model_(&model), anisoMax_(options.anisoMax), log_(&log) {
  const MeshConstraints& c = model.meshConstraints();
  for (const auto& [tag, def] : c.sizeFields) {
    const std::optional<Type> type = fieldTypeNamed(def.type);
    if (!type) {
      log.warning("Field[" + std::to_string(tag) + "] = " + def.type +
                  " is not a supported field type; it reads as 1e22");
      continue;
    }
    fields_.emplace(tag, compile(model, tag, def, *type, options, log));
  }
  for (int tag : fieldsInCycles(fields_)) {
    log.warning("Field[" + std::to_string(tag) + "] depends on itself; it reads as 1e22");
    fields_.erase(tag);
  }
  for (int tag : c.boundaryLayerFields) {
    const auto it = fields_.find(tag);
    if (it != fields_.end() && it->second.type == Type::BoundaryLayer)
      layerFields_.push_back(tag);
    else
      log.warning("BoundaryLayer Field = " + std::to_string(tag) + ": " +
                  (it == fields_.end() ? "field not defined" : "not a BoundaryLayer field") +
                  "; ignored");
  }
  background_ = c.backgroundField;
  if (background_ != 0 && !fields_.contains(background_))
    log.warning("Background Field = " + std::to_string(background_) + " is not defined; ignored");
  if (const int index = c.backgroundView; index >= 0) {
    if (const post::View* view = viewNamed(options.views, index, -1))
      backgroundView_ = std::make_unique<ViewSize>(*view, ViewSize::Options{});
    else
      log.warning("Background Mesh View[" + std::to_string(index) + "]: there is no view at index " +
                  std::to_string(index) + "; ignored");
  }
}

SizeFields::~SizeFields() = default;
SizeFields::SizeFields(SizeFields&&) noexcept = default;
SizeFields& SizeFields::operator=(SizeFields&&) noexcept = default;

void SizeFields::evaluate(std::span<const Vec3> points, EntityId where,
                          std::span<double> sizes) const {
  for (std::size_t k = 0; k < points.size(); ++k) sizes[k] = at(points[k], where);
}

std::vector<const BoundaryLayerParameters*> SizeFields::boundaryLayers() const {
  std::vector<const BoundaryLayerParameters*> layers;
  for (int tag : layerFields_) layers.push_back(fields_.at(tag).layer.get());
  return layers;
}

void SizeFields::warning(std::string_view message) const {
  if (log_) log_->warning(message);
}

bool SizeFields::hasBackgroundField() const {
  return background_ != 0 && fields_.contains(background_);
}

bool SizeFields::hasBackground() const { return hasBackgroundField() || backgroundView_; }

// The metric of one field: its own for MathEvalAniso and a PostView of a tensor view, else
// I/h^2 from its size h (a size <= 0 or not finite asks for nothing).
std::array<double, 6> SizeFields::fieldMetric(const Field& f, Vec3 p, EntityId where) const {
  if (f.type == Type::MathEvalAniso) {
    std::array<double, 6> m{};  // M11 M22 M33 M12 M13 M23
    for (std::size_t k = 0; k < 6; ++k) m[k] = formula(*f.expressions[k], p, where, 1);
    return {m[0], m[3], m[4], m[1], m[5], m[2]};
  }
  if (f.type == Type::PostView && f.view && f.view->anisotropic())
    if (const auto t = f.view->tensor(p)) return *t;
  const double h = evaluateField(f, p, where, 1);
  return sizeTensor(h);
}

std::optional<std::array<double, 6>> SizeFields::metric(Vec3 point, EntityId where) const {
  if (!hasBackground()) return std::nullopt;
  std::optional<SymmetricTensor> m;
  if (hasBackgroundField())
    m = boundedAnisotropy(fieldMetric(fields_.at(background_), point, where), anisoMax_);
  if (backgroundView_) {
    std::optional<SymmetricTensor> t = backgroundView_->tensor(point);
    if (!t) {
      const double h = backgroundView_->size(point);
      t = sizeTensor(h);
    }
    const SymmetricTensor v = boundedAnisotropy(*t, anisoMax_);
    m = m ? boundedAnisotropy(intersectMetrics(*m, v), anisoMax_) : v;
  }
  return m;
}

bool SizeFields::hasAnisotropicBackground() const {
  if (backgroundView_ && backgroundView_->anisotropic()) return true;
  if (!hasBackgroundField()) return false;
  const Field& f = fields_.at(background_);
  return f.type == Type::MathEvalAniso ||
         (f.type == Type::PostView && f.view && f.view->anisotropic());
}

double SizeFields::at(Vec3 point, EntityId where) const {
  double h = hasBackgroundField() ? value(background_, point, where) : kUnbounded;
  if (backgroundView_) h = std::min(h, backgroundView_->size(point));
  return h;
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

double SizeFields::formula(const MathExpression& e, Vec3 p, EntityId where, int depth) const {
  const std::vector<int>& used = e.fieldsUsed();
  double values[16];
  std::vector<double> many;
  double* v = values;
  if (used.size() > 16) many.resize(used.size()), v = many.data();
  for (std::size_t k = 0; k < used.size(); ++k) v[k] = valueAtDepth(used[k], p, where, depth);
  return e.evaluate(p.x, p.y, p.z, {v, used.size()});
}

// The types that read Field[InField] around p, or at a mapped point.
double SizeFields::evaluateDerived(const Field& f, Vec3 p, EntityId where, int depth) const {
  const int in = f.inField();
  const auto g = [&](Vec3 q) { return valueAtDepth(in, q, where, depth); };
  const double h = f.number(Slot::Delta);
  switch (f.type) {
    case Type::Octree: return g(p);
    case Type::Param:
      return g({formula(*f.expressions[0], p, where, depth),
                formula(*f.expressions[1], p, where, depth),
                formula(*f.expressions[2], p, where, depth)});
    case Type::Gradient: {
      const Vec3 gradient = differenceGradient(g, p, h);
      switch (rounded(f.number(Slot::Kind))) {
        case 0: return gradient.x;
        case 1: return gradient.y;
        case 2: return gradient.z;
        case 3: return norm(gradient);
        default: return kUnbounded;
      }
    }
    case Type::Curvature: return differenceCurvature(g, p, h);
    case Type::Laplacian: return differenceLaplacian(g, p, h);
    case Type::Mean: return differenceMean(g, p, h);
    case Type::MaxEigenHessian: return largestEigenvalue(differenceHessian(g, p, h));
    default: return kUnbounded;
  }
}

double SizeFields::evaluateField(const Field& f, Vec3 p, EntityId where, int depth) const {
  switch (f.type) {
    case Type::Constant:
      return inEntities(f.entities, where, f.number(Slot::IncludeBoundary) != 0)
                 ? f.number(Slot::VIn)
                 : f.number(Slot::VOut);
    case Type::Restrict:
      return inEntities(f.entities, where, f.number(Slot::IncludeBoundary) != 0)
                 ? valueAtDepth(f.inField(), p, where, depth)
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
    case Type::Frustum: return frustum(f, p);
    case Type::Distance: return f.samples->distanceTo(p);
    case Type::AttractorAnisoCurve:
      return f.samples->empty() ? kUnbounded : anisoCurveSize(f, f.samples->distanceTo(p));
    case Type::Threshold: return threshold(f, valueAtDepth(f.inField(), p, where, depth));
    case Type::MathEval: return formula(*f.expression, p, where, depth);
    case Type::MathEvalAniso: {
      std::array<double, 6> m{};  // M11 M22 M33 M12 M13 M23, the order of the options
      for (std::size_t k = 0; k < 6; ++k) m[k] = formula(*f.expressions[k], p, where, depth);
      const double largest = largestEigenvalue(m);
      return largest > 0 ? 1 / std::sqrt(largest) : kUnbounded;
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
    case Type::Extend: return f.extension->at(p, where.dim);
    case Type::Automatic: return f.automatic->at(p);
    case Type::ExternalProcess: return kUnbounded;
    case Type::PostView: return f.view ? f.view->size(p) : kUnbounded;
    case Type::Adapt: return f.adapt ? f.adapt->at(p) : kUnbounded;
    case Type::BoundaryLayer: return f.layer->sizeAt((*f.wallDistance)(p));
    default: return evaluateDerived(f, p, where, depth);
  }
}

}  // namespace geomesh
