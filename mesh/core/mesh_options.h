// MeshOptions: the Mesh.* options the generators read, gathered from the option registry.
#pragma once

namespace geomesh {

class Mesh;

namespace post {
class ViewStore;
}

// The Mesh.* options the generators read, gathered by the session from the option registry.
struct MeshOptions {
  double sizeMin = 0;        // Mesh.MeshSizeMin
  double sizeMax = 1e22;     // Mesh.MeshSizeMax
  double sizeFactor = 1;     // Mesh.MeshSizeFactor
  bool sizeFromPoints = true;          // Mesh.MeshSizeFromPoints
  bool sizeExtendFromBoundary = true;  // Mesh.MeshSizeExtendFromBoundary
  double sizeFromCurvature = 0;        // Mesh.MeshSizeFromCurvature: elements per 2*Pi, 0: off
  int minCircleNodes = 7;              // Mesh.MinimumCircleNodes: per full turn of an arc
  int minCurveNodes = 3;               // Mesh.MinimumCurveNodes: curves neither straight nor arcs
  int algorithm2D = 6;       // Mesh.Algorithm
  int algorithm3D = 1;       // Mesh.Algorithm3D
  int smoothing = 1;         // Mesh.Smoothing
  int elementOrder = 1;      // Mesh.ElementOrder
  bool secondOrderLinear = false;      // Mesh.SecondOrderLinear: high-order nodes on straight edges
  bool secondOrderIncomplete = false;  // Mesh.SecondOrderIncomplete: serendipity elements
  int highOrderOptimize = 0;           // Mesh.HighOrderOptimize (0 none, 1..4 repair methods)
  double highOrderThresholdMin = 0.1;  // Mesh.HighOrderThresholdMin: scaled Jacobian to reach
  double highOrderThresholdMax = 2;    // Mesh.HighOrderThresholdMax
  int highOrderNumLayers = 6;          // Mesh.HighOrderNumLayers: layers around a bad element
  int numThreads = 1;        // General.NumThreads
  double randomFactor = 1e-9;  // Mesh.RandomFactor
  bool recombineAll = false;       // Mesh.RecombineAll
  int recombinationAlgorithm = 1;  // Mesh.RecombinationAlgorithm (0 simple, 1 blossom)
  double recombineMinQuality = 0.01;    // Mesh.RecombineMinimumQuality (corner-angle quality)
  int recombineOptimizeTopology = 5;    // Mesh.RecombineOptimizeTopology: clean-up passes
  bool recombineNodeRepositioning = true;  // Mesh.RecombineNodeRepositioning
  int subdivisionAlgorithm = 0;  // Mesh.SubdivisionAlgorithm (1: all quadrangles, 2: hexahedra)
  bool optimize = true;            // Mesh.Optimize: improve tetrahedra below the threshold
  double optimizeThreshold = 0.3;  // Mesh.OptimizeThreshold (gamma)
  double anisoMax = 1e33;          // Mesh.AnisoMax: largest aspect ratio of the metric
  double smoothRatio = 1.8;        // Mesh.SmoothRatio: metric gradation (anisotropic 2D)
  double compoundSizeFactor = 0.5;  // Mesh.CompoundMeshSizeFactor: a compound's first meshes
  int compoundClassify = 1;         // Mesh.CompoundClassify
  // The session's views, for Background Mesh View and PostView fields; null when none.
  const post::ViewStore* views = nullptr;
  // The mesh of the merged file that the model's discrete surfaces come from (Merge
  // "x.stl"): their triangles are copied from it, never meshed again. Null when none.
  const Mesh* discreteMesh = nullptr;
};

}  // namespace geomesh
