// XAO files of the OpenCASCADE factory: the shape as BREP text inside XML, with its entities.
#pragma once

#include <TopoDS_Shape.hxx>

#include <string>
#include <vector>

#include "kernel/occ/occ_shapes.h"

namespace geomesh {

// An entity an XAO file lists: its dimension, its sub-shape and, when geomesh wrote the file,
// its tag (0 otherwise).
struct XaoEntity {
  int dim;
  int tag;
  TopoDS_Shape shape;
};

// A group of entities of one dimension (<group dimension="face" tag="3" name="..">), its
// elements given by their sub-shapes.
struct XaoGroup {
  int dim;
  int tag;
  std::string name;
  std::vector<TopoDS_Shape> elements;
};

struct XaoContents {
  TopoDS_Shape shape;
  std::vector<XaoEntity> entities;
  std::vector<XaoGroup> groups;
};

// Writes `compound` (holding every bound shape) as an XAO file: the BREP text in a CDATA
// section, then the vertices, edges, faces and solids, each naming its sub-shape by its index
// among the compound's sub-shapes (as XAO does) and carrying its tag (and a vertex its exact
// point: the BREP text rounds it to 15 digits). Written to a temporary
// file renamed at the end, so that a failure leaves no partial file behind.
void writeXao(const OccShapes& shapes, const TopoDS_Shape& compound, const std::string& path);

// Reads an XAO file (vertices listing their exact point get it back); throws GeometryError
// naming the path when it is not one.
XaoContents readXao(const std::string& path);

}  // namespace geomesh
