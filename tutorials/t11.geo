// t11: a valve handwheel from curved OpenCASCADE surfaces: a turned hub, a torus rim,
// spokes, and sizes that follow the curvature.
//
// CAD parts are mostly curved faces: cylinders, cones, spheres, tori, surfaces of revolution
// and B-spline patches. Each is meshed in its own parameter plane and mapped onto the
// surface, which raises two questions this part answers: seams (a closed face such as a
// cylinder or a torus is cut open along a curve that bounds it twice, once from each side)
// and poles (where a whole edge of the parameter plane collapses to one point, at the tip of
// a sphere or of a turned profile that touches its axis).

SetFactory("OpenCASCADE");

DefineConstant[ rimRadius = 5, rimThickness = 0.6, spokes = 4, curvature = 16 ];

// The hub: a profile in the xz-plane, turned a full turn about the z-axis. Its outer side is
// a B-spline through five points; its bottom and top end on the axis, so the turned face
// has a pole at each end. `Extrude{{axis}, {point on axis}, angle}{Surface{..};}` turns a
// face into a solid of revolution; the list it returns starts with the far face (here the
// profile again, since the turn is whole), then the volume, then the faces the profile's
// curves swept. After a whole turn the profile lies inside the solid and bounds nothing, so
// it is deleted.
Point(1) = {0, 0, -0.8};
Point(2) = {1.4, 0, -0.8};
Point(3) = {1.6, 0, -0.3};
Point(4) = {1.2, 0, 0.3};
Point(5) = {0.9, 0, 0.8};
Point(6) = {0.5, 0, 1.2};
Point(7) = {0, 0, 1.2};
Line(1) = {1, 2};
BSpline(2) = {2, 3, 4, 5, 6};
Line(3) = {6, 7};
Line(4) = {7, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
hub[] = Extrude {{0, 0, 1}, {0, 0, 0}, 2 * Pi} { Surface{1}; };
Printf("the hub is volume %g, with %g faces swept", hub[1], #hub[] - 2);
Delete { Surface{1}; }

// The rim: a torus (centre, the radius of its centre circle, the radius of its tube). A
// torus has two seams: one around the tube, one around the axis.
Torus(100) = {0, 0, 0, rimRadius, rimThickness};

// The spokes: cylinders from the hub into the rim, turned about the axis in a loop.
spokeTags[] = {};
For i In {0 : spokes - 1}
  s = newv;
  Cylinder(s) = {0.8, 0, 0, rimRadius - 0.8, 0, 0, 0.3};
  Rotate {{0, 0, 1}, {0, 0, 0}, 2 * Pi * i / spokes} { Volume{s}; }
  spokeTags[] += s;
EndFor

// One solid: the union of everything. Where a spoke enters the hub or the rim, the faces are
// cut along their intersection curve; the faces after the union are trimmed surfaces whose
// holes lie across seams, and the mesh stays conforming across every shared curve.
wheel[] = BooleanUnion{ Volume{hub[1]}; Delete; }{ Volume{100, spokeTags[]}; Delete; };
Printf("%g volume after the union", #wheel[]);

// Sizes. `Mesh.MeshSizeFromCurvature = n` asks for about n elements per full turn of every
// curve and face: the thin rim tube and the spokes get small elements around their
// circumference, the flatter parts of the hub larger ones, up to Mesh.MeshSizeMax and no
// smaller than Mesh.MeshSizeMin.
Mesh.MeshSizeFromCurvature = curvature;
Mesh.MeshSizeMax = 0.8;
Mesh.MeshSizeMin = 0.1;

// The whole skin of the wheel (`Boundary` lists a volume's faces, signed by orientation) and
// the flat top of the hub, found by where it lies.
Physical Volume("wheel") = wheel[];
Physical Surface("skin") = Abs(Boundary{ Volume{wheel[]}; });
Physical Surface("hub top") = Surface In BoundingBox{-1, -1, 1.1, 1, 1, 1.3};
