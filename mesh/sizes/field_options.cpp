// Field option tables: type names, option names and aliases, defaults per type.
#include "mesh/sizes/field_options.h"

#include <utility>

namespace geomesh {
namespace {

using T = SizeFields::Type;
using S = SizeFields::Slot;

constexpr double kUnbounded = 1e22;

constexpr const char* kSlotNames[SizeFields::kSlotCount] = {
    "VIn",      "VOut",     "XMin",     "XMax",     "YMin",          "YMax",
    "ZMin",     "ZMax",     "Thickness", "Radius",  "XCenter",       "YCenter",
    "ZCenter",  "XAxis",    "YAxis",    "ZAxis",    "Sampling",      "InField",
    "SizeMin",  "SizeMax",  "DistMin",  "DistMax",  "Sigmoid",       "StopAtDistMax",
    "IncludeBoundary",
    "Delta",    "Kind",     "X1",       "Y1",       "Z1",            "X2",
    "Y2",       "Z2",       "InnerR1",  "OuterR1",  "InnerR2",       "OuterR2",
    "InnerV1",  "OuterV1",  "InnerV2",  "OuterV2",  "Power",         "SizeMinTangent",
    "SizeMaxTangent", "SizeMinNormal", "SizeMaxNormal", "hBulk",     "hMin",
    "hMax",     "gradation", "features", "nPointsPerCircle", "nPointsPerGap", "smoothing",
    "ViewIndex", "ViewTag", "CropNegativeValues", "UseClosest", "View", "Order", "Dimension",
    "TargetElements", "TargetError"};

// Layers per gap when the script gives none. The reference reports an uninitialised number
// for this default; 2 is the count its automatic size field falls back to.
constexpr double kDefaultPointsPerGap = 2;

}  // namespace

std::optional<SizeFields::Type> fieldTypeNamed(const std::string& name) {
  static const std::pair<const char*, T> kTypes[] = {
      {"Constant", T::Constant},
      {"Box", T::Box},
      {"Ball", T::Ball},
      {"Cylinder", T::Cylinder},
      {"Distance", T::Distance},
      {"Attractor", T::Distance},
      {"Threshold", T::Threshold},
      {"MathEval", T::MathEval},
      {"Min", T::Min},
      {"Max", T::Max},
      {"Restrict", T::Restrict},
      {"Frustum", T::Frustum},
      {"Param", T::Param},
      {"Gradient", T::Gradient},
      {"Curvature", T::Curvature},
      {"Laplacian", T::Laplacian},
      {"MaxEigenHessian", T::MaxEigenHessian},
      {"Mean", T::Mean},
      {"Octree", T::Octree},
      {"Extend", T::Extend},
      {"MathEvalAniso", T::MathEvalAniso},
      {"AttractorAnisoCurve", T::AttractorAnisoCurve},
      {"AutomaticMeshSizeField", T::Automatic},
      {"ExternalProcess", T::ExternalProcess},
      {"PostView", T::PostView},
      {"Adapt", T::Adapt},
      {"BoundaryLayer", T::BoundaryLayer}};
  for (const auto& entry : kTypes)
    if (name == entry.first) return entry.second;
  return std::nullopt;
}

std::string canonicalFieldOption(const std::string& name) {
  static const std::pair<const char*, const char*> kAliases[] = {
      {"NodesList", "PointsList"},     {"VerticesList", "PointsList"},
      {"EdgesList", "CurvesList"},     {"FacesList", "SurfacesList"},
      {"RegionsList", "VolumesList"},  {"NNodesByEdge", "Sampling"},
      {"NumPointsPerCurve", "Sampling"}, {"IField", "InField"}, {"IView", "ViewIndex"},
      {"LcMin", "SizeMin"},            {"LcMax", "SizeMax"},
      {"lMinTangent", "SizeMinTangent"}, {"lMaxTangent", "SizeMaxTangent"},
      {"lMinNormal", "SizeMinNormal"}, {"lMaxNormal", "SizeMaxNormal"},
      {"R1_inner", "InnerR1"},         {"R1_outer", "OuterR1"},
      {"R2_inner", "InnerR2"},         {"R2_outer", "OuterR2"},
      {"V1_inner", "InnerV1"},         {"V1_outer", "OuterV1"},
      {"V2_inner", "InnerV2"},         {"V2_outer", "OuterV2"},
      {"hwall_n", "Size"},             {"hfar", "SizeFar"},
      {"FanNodesList", "FanPointsList"}};
  for (const auto& alias : kAliases)
    if (name == alias.first) return alias.second;
  return name;
}

const char* slotName(SizeFields::Slot slot) { return kSlotNames[static_cast<int>(slot)]; }

std::vector<SlotDefault> numericOptions(SizeFields::Type t) {
  constexpr double kStep = 1e-4;  // finite difference step (Delta)
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
    case T::Frustum:
      return {{S::X1, 0},      {S::Y1, 0},      {S::Z1, 1},      {S::X2, 0},
              {S::Y2, 0},      {S::Z2, 0},      {S::InnerR1, 0}, {S::OuterR1, 1},
              {S::InnerR2, 0}, {S::OuterR2, 1}, {S::InnerV1, 0.1}, {S::OuterV1, 1},
              {S::InnerV2, 0.1}, {S::OuterV2, 1}};
    case T::Param:
    case T::Octree: return {{S::InField, 1}};
    case T::Gradient: return {{S::InField, 1}, {S::Delta, kStep}, {S::Kind, 3}};
    case T::Curvature:
    case T::Laplacian:
    case T::MaxEigenHessian:
    case T::Mean: return {{S::InField, 1}, {S::Delta, kStep}};
    case T::Extend: return {{S::DistMax, 1}, {S::Power, 1}, {S::SizeMax, 1}};
    case T::AttractorAnisoCurve:
      return {{S::Sampling, 20},         {S::DistMin, 0.1},         {S::DistMax, 0.5},
              {S::SizeMinTangent, 0.5},  {S::SizeMaxTangent, 0.5},  {S::SizeMinNormal, 0.05},
              {S::SizeMaxNormal, 0.5}};
    case T::Automatic:
      return {{S::HBulk, -1},      {S::HMin, -1},           {S::HMax, -1},
              {S::Gradation, 1.1}, {S::Features, 1},        {S::PointsPerCircle, 20},
              {S::PointsPerGap, kDefaultPointsPerGap}, {S::Smoothing, 1}};
    case T::PostView:
      return {{S::ViewIndex, 0}, {S::ViewTag, -1}, {S::CropNegativeValues, 1}, {S::UseClosest, 1}};
    case T::Adapt:
      return {{S::View, -1},          {S::Order, 2},       {S::Dimension, -1},
              {S::TargetElements, 0}, {S::TargetError, 0}, {S::SizeMin, 0},
              {S::SizeMax, kUnbounded}};
    case T::MathEval:
    case T::MathEvalAniso:
    case T::BoundaryLayer:  // its options are read by boundary_layer_field.h
    case T::ExternalProcess:
    case T::Min:
    case T::Max: return {};
  }
  return {};
}

std::vector<StringOption> stringOptions(SizeFields::Type t) {
  switch (t) {
    case T::MathEval: return {{"F", "F2 + Sin(z)"}};
    case T::MathEvalAniso:
      return {{"M11", "F2 + Sin(z)"}, {"M22", "F2 + Sin(z)"}, {"M33", "F2 + Sin(z)"},
              {"M12", "F2 + Sin(z)"}, {"M13", "F2 + Sin(z)"}, {"M23", "F2 + Sin(z)"}};
    case T::Param: return {{"FX", ""}, {"FY", ""}, {"FZ", ""}};
    case T::ExternalProcess: return {{"CommandLine", ""}};
    case T::Automatic: return {{"p4estFileToLoad", ""}};
    default: return {};
  }
}

int listDimension(const std::string& name) {
  if (name == "PointsList") return 0;
  if (name == "CurvesList") return 1;
  if (name == "SurfacesList") return 2;
  if (name == "VolumesList") return 3;
  return -1;
}

bool takesEntityList(SizeFields::Type t, int dim) {
  switch (t) {
    case T::Distance:
    case T::Constant:
    case T::Restrict: return true;
    case T::AttractorAnisoCurve: return dim == 1;
    case T::Extend: return dim == 1 || dim == 2;
    default: return false;
  }
}

bool takesFieldsList(SizeFields::Type t) { return t == T::Min || t == T::Max; }

}  // namespace geomesh
