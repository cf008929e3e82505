// t8: a bearing block built from solids with OpenCASCADE, refined inside around its bore.
//
// Instead of points, curves and loops, the OpenCASCADE kernel starts from whole solids and
// combines them with Boolean operations. This block is a box with a flange, a bore through
// it, two bolt holes and rounded vertical edges.

SetFactory("OpenCASCADE");

// Parameters, overridable with -setnumber.
DefineConstant[ width = 6, depth = 3, height = 2, boreRadius = 0.8, size = 0.3 ];

// Primitives take their dimensions directly: Box{x, y, z, dx, dy, dz} (a corner and the
// extents), Cylinder{x, y, z, ax, ay, az, r} (the centre of its base, its axis, its radius).
Box(1) = {0, 0, 0, width, depth, height};
Box(2) = {width / 2 - 1.2, 0, height, 2.4, depth, 1.2};   // the boss the bore goes through
Cylinder(3) = {width / 2, -0.1, height, 0, depth + 0.2, 0, boreRadius};
Cylinder(4) = {0.8, depth / 2, -0.1, 0, 0, height + 0.2, 0.3};
Cylinder(5) = {width - 0.8, depth / 2, -0.1, 0, 0, height + 0.2, 0.3};

// A union fuses the base and the boss into one volume. "Delete;" removes the inputs from the
// model, so only the result is left. The result gets a new tag: the operation returns it.
block() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };

// A difference removes the tools from the object: the bore and the two bolt holes.
block() = BooleanDifference{ Volume{block(0)}; Delete; }{ Volume{3, 4, 5}; Delete; };
Printf("the block is volume %g", block(0));

// Rounding edges: Fillet{volumes}{curves}{radius}. The vertical edges at the corners are
// found by where they lie rather than by their tags: `Curve In BoundingBox{..}` lists the
// curves inside a box, here a thin column around each corner.
e = 1e-3;
corners() = {};
For i In {0:1}
  For j In {0:1}
    x = i * width;
    y = j * depth;
    corners() += Curve In BoundingBox{x - e, y - e, -e, x + e, y + e, height + e};
  EndFor
EndFor
block() = Fillet{block(0)}{corners()}{0.4};
Printf("%g corner edges rounded", #corners());

// Faces are found the same way: the bore's face is the one inside a box around its axis.
bore() = Surface In BoundingBox{width / 2 - boreRadius - e, -e, height - boreRadius - e,
                                width / 2 + boreRadius + e, depth + e,
                                height + boreRadius + e};
bottom() = Surface In BoundingBox{-e, -e, -e, width + e, depth + e, e};
Physical Volume("block") = block(0);
Physical Surface("bore") = bore();
Physical Surface("bottom") = bottom();

// Sizes: a uniform bound, and finer near the bore. A Distance field measures how far a point
// is from the bore's face; a Threshold field turns that into a size: size / 3 within 0.2 of
// the bore, growing to `size` at 1.5 from it. The background field applies everywhere,
// inside the volume too: the tetrahedra grow away from the bore.
Mesh.MeshSizeMax = size;
Field[1] = Distance;
Field[1].SurfacesList = {bore()};
Field[2] = Threshold;
Field[2].InField = 1;
Field[2].SizeMin = size / 3;
Field[2].SizeMax = size;
Field[2].DistMin = 0.2;
Field[2].DistMax = 1.5;
Background Field = 2;

// Run with: geomesh t8.geo -3
