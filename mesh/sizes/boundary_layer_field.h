// BoundaryLayerParameters: a BoundaryLayer field's options, its layer heights and its size.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "kernel/messages.h"
#include "kernel/model.h"

namespace geomesh {

// The options of one `Field[n] = BoundaryLayer`, with the reference's defaults. The 2D
// surface mesher builds the layer from them (BoundaryLayer Field = n); read as a size field,
// the field gives the layer's cell size at the distance from its curves (see sizeAt).
struct BoundaryLayerParameters {
  int tag = 0;                        // the field's
  std::vector<int> curves;            // CurvesList (EdgesList)
  std::vector<int> points;            // PointsList (NodesList)
  std::vector<int> excludedSurfaces;  // ExcludedSurfacesList
  std::vector<int> fanPoints;         // FanPointsList (FanNodesList)
  std::vector<int> fanPointsSizes;    // FanPointsSizesList: elements of each fan
  std::vector<double> sizes;          // SizesList: first-cell height per PointsList point
  double size = 0.1;                  // Size (hwall_n): first-cell height
  double sizeFar = 1;                 // SizeFar (hfar)
  double ratio = 1.1;                 // Ratio: growth of the heights
  double thickness = 0.01;            // Thickness: the layer stops below it
  int layers = 10;                    // NbLayers (with BetaLaw)
  bool betaLaw = false;               // BetaLaw
  double beta = 1.01;                 // Beta
  bool quads = false;                 // Quads: quadrangles, else two triangles per cell
  bool intersectMetrics = false;      // IntersectMetrics (read, not used in 2D)
  double anisoMax = 1e10;             // AnisoMax (read, not used in 2D)

  bool hasCurve(int tag) const;
  bool excludes(int surface) const;
  bool isFanPoint(int point) const;
  // Elements of the fan at `point`, `fallback` (Mesh.BoundaryLayerFanElements) when
  // FanPointsSizesList gives none for it.
  int fanElements(int point, int fallback) const;
  // The first-cell height at a model point: its SizesList entry when the point is in
  // PointsList and SizesList has one for it, else Size.
  double firstHeight(int point) const;
  // The distances from the wall of the layer's nodes, from the first (`first`) to the top:
  // geometric (h1 = first, h(k+1) = h(k) Ratio) up to Thickness; with BetaLaw, NbLayers
  // heights following the Beta law, scaled so that the first is `first`.
  std::vector<double> heights(double first) const;
  // The isotropic size at distance d from the wall: the cell height there, Size + d (Ratio -
  // 1), capped by SizeFar.
  double sizeAt(double d) const;
};

class PointCloud;

// The distance from a point to a set of curves, each taken as a fine polyline of samples:
// the nearest sample is found first, then the nearest point on its two segments.
class CurveDistance {
 public:
  CurveDistance(const Model& model, const std::vector<int>& curves);
  ~CurveDistance();
  double operator()(Vec3 p) const;  // 1e22 without curves

 private:
  std::vector<Vec3> samples_;
  std::vector<int> piece_;  // the curve each sample is on, numbered from 0
  std::unique_ptr<PointCloud> cloud_;
};

// Reads the options of a BoundaryLayer field definition (older names accepted: EdgesList,
// NodesList, FanNodesList, hwall_n, hfar, thickness, ratio, ExcludedFaceList,
// hwall_n_nodes); an option the field does not have is reported to
// `log` under the name `field` ("Field[3]") and ignored.
void readBoundaryLayerOptions(BoundaryLayerParameters& p, const std::string& field,
                              const SizeFieldDefinition& def, MessageSink& log);

}  // namespace geomesh
