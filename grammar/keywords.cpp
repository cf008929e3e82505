// The tables of command words, tail words, attribute names and built-in function names.
#include "grammar/keywords.h"

#include <algorithm>

namespace geomesh {

namespace {

// Words that start or continue a command (statement heads and shape kinds).
constexpr std::string_view kCommandWords[] = {
    "Abort", "AdaptMesh", "Affine", "BSpline", "Background", "Bezier", "Block", "BooleanDifference",
    "BooleanFragments", "BooleanIntersection", "BooleanUnion", "Boundary", "BoundaryLayer",
    "BoundingBox", "Box",
    "CatmullRom", "Chamfer", "Characteristic", "Circle", "ClassifySurfaces", "Closest", "Coherence", "Cohomology",
    "Color", "Combine", "CombinedBoundary", "Compound", "Cone", "CreateGeometry", "CreateTopology", "Curve",
    "Cylinder", "Delete", "Dilate", "Disk", "Draw", "Duplicata", "Ellipse", "Ellipsis", "Error", "Exit",
    "Extrude", "Field", "Fillet", "Filling", "General", "Geometry", "HealShapes", "Hide", "Hole",
    "Homology", "Include", "Layers", "Length", "Line", "Loop", "Merge", "Mesh", "MeshAlgorithm",
    "MeshSize", "NewModel", "NonBlockingSystem", "NonBlockingSystemCall", "Nurbs", "OptimizeMesh", "PartitionMesh", "Periodic",
    "Physical", "Physicals", "Plane", "Point", "PointsOf", "PolarSphere", "PostProcessing", "Print", "Printf",
    "QuadTriAddVerts", "QuadTriNoNewVerts", "Recombine", "Rectangle", "Recursive", "RefineMesh",
    "RelocateMesh", "RenumberMeshElements", "RenumberMeshNodes", "ReorientMesh", "Reverse",
    "Rotate", "Ruled", "Save", "SetChanged", "SetFactory", "SetNumber", "SetOrder", "SetString",
    "ShapeFromFile", "Show", "Sleep", "Smoother", "Solver", "Sphere", "Spline", "Split", "Surface",
    "Symmetry", "SyncModel", "System", "SystemCall", "ThruSections", "Torus", "Transfinite", "Translate", "View",
    "Volume", "Warning", "Wedge", "Wire",
};

// Words that only appear after a shape: Point{1} In Surface{2}; ... Using Progression 2;
constexpr std::string_view kTailWords[] = {
    "Alternate", "AlternateLeft", "AlternateRight", "Alternated", "Beta",
    "Bump",      "Knots",         "Left",           "Order",      "Power",      "Progression",
    "Right",     "Using",
};

// Attribute names inside DefineConstant[...] / DefineNumber[...] / DefineString[...].
constexpr std::string_view kAttributeNames[] = {
    "AutoCheck", "ChangedValue", "Choices", "Closed", "Graph", "GmshOption", "Help",
    "Highlight", "Kind", "Label", "Loop", "Macro", "Max", "Min", "Name", "NeverChanged", "Path",
    "ReadOnly", "ReadOnlyRange", "ServerAction", "ShortHelp", "Step", "Units", "Visible",
};

// Built-in functions: Gmsh reserves their names, so Name[args] calls them as Name(args) does.
constexpr std::string_view kFunctionNames[] = {
    "AbsolutePath", "Abs", "Acos", "Acosh", "ArcCos", "ArcSin", "ArcTan", "ArcTan2", "Asin",
    "Asinh", "Atan", "Atan2", "Atanh", "Ceil", "Cos", "Cosh", "DimNameSpace", "DirName", "Exists",
    "Exp", "Fabs", "FileExists", "Find", "Floor", "Fmod", "GetEnv", "GetForced", "GetNumber",
    "GetString", "GetStringValue", "GetValue", "Hypot", "LinSpace", "ListFromFile", "Log", "Log10", "LogSpace",
    "LowerCase", "LowerCaseIn", "Max", "Min", "Modulo", "NameStruct", "NameToString", "Rand", "Round", "S2N",
    "Sin", "Sign", "Sinh",  // Sin first: the likelier meaning of a misspelled "Sinn"
    "Sprintf", "Sqrt", "Step", "Str", "StrCat", "StrChoice", "StrCmp", "StrFind", "StrLen",
    "StrPrefix", "StrRelative", "StrReplace", "StrSub", "Tan", "Tanh", "TextAttributes", "Unique",
    "UpperCase",
};

}  // namespace

std::span<const std::string_view> functionNames() { return kFunctionNames; }

bool isFunctionName(std::string_view name) {
  return std::find(std::begin(kFunctionNames), std::end(kFunctionNames), name) !=
         std::end(kFunctionNames);
}

std::span<const std::string_view> commandWords() { return kCommandWords; }
std::span<const std::string_view> tailWords() { return kTailWords; }
std::span<const std::string_view> attributeNames() { return kAttributeNames; }

}  // namespace geomesh
