// SizeFields: the Box, Ball, Distance, Threshold, MathEval, Min/Max, Restrict size fields.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "kernel/model.h"

namespace geomesh {

class MathExpression;
class PointCloud;

// The mesh size fields a script defined (Field[n] = Type; Field[n].Option = v), compiled for
// evaluation, and the background field (Background Field = n) that the 1D and 2D meshers
// follow. Types: Constant, Box, Ball, Cylinder, Distance (alias Attractor), Threshold,
// MathEval, Min, Max, Restrict; older option names are accepted (NodesList, EdgesList,
// FacesList, NNodesByEdge/NumPointsPerCurve, IField, LcMin, LcMax). An unknown type or option
// is reported once to the log and ignored; a field reading an undefined field, or a cycle of
// fields, reads 1e22 there.
class SizeFields {
 public:
  SizeFields(const Model& model, MessageSink& log);
  ~SizeFields();
  SizeFields(SizeFields&&) noexcept;
  SizeFields& operator=(SizeFields&&) noexcept;

  bool hasBackground() const { return background_ != 0 && fields_.contains(background_); }
  // The background field's sizes at `points`, which lie on entity `where` (some fields,
  // Restrict and Constant, depend on it).
  void evaluate(std::span<const Vec3> points, EntityId where, std::span<double> sizes) const;
  double at(Vec3 point, EntityId where) const;
  // Field `tag` at a point (1e22 if undefined).
  double value(int tag, Vec3 point, EntityId where) const;

  enum class Type {
    Constant, Box, Ball, Cylinder, Distance, Threshold, MathEval, Min, Max, Restrict
  };
  // Numeric options, by position (each type uses some of them).
  enum class Slot : std::uint8_t {
    VIn, VOut, XMin, XMax, YMin, YMax, ZMin, ZMax, Thickness, Radius, XCenter, YCenter,
    ZCenter, XAxis, YAxis, ZAxis, Sampling, InField, SizeMin, SizeMax, DistMin, DistMax,
    Sigmoid, StopAtDistMax, IncludeBoundary
  };
  static constexpr int kSlotCount = 25;
  struct Field {
    Type type = Type::Constant;
    std::array<double, kSlotCount> slots = {};
    std::vector<int> fieldsList;             // Min, Max (FieldsList)
    std::vector<EntityId> entities;          // Distance, Constant, Restrict lists
    std::unique_ptr<MathExpression> expression;
    std::unique_ptr<PointCloud> samples;     // Distance
    double number(Slot s) const { return slots[static_cast<std::size_t>(s)]; }
  };

 private:
  double evaluateField(const Field& f, Vec3 p, EntityId where, int depth) const;
  double valueAtDepth(int tag, Vec3 p, EntityId where, int depth) const;
  bool inEntities(const std::vector<EntityId>& list, EntityId where, bool withBoundary) const;

  const Model* model_;
  std::map<int, Field> fields_;
  int background_ = 0;
};

}  // namespace geomesh
