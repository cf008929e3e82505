// A roller built from two half cylinders: structured grid on its circle-arc edges and lateral faces, tets inside.
SetFactory("OpenCASCADE");
R = 0.4; H = 1.2;
Cylinder(1) = {0, 0, 0, 0, 0, H, R, Pi};
Cylinder(2) = {0, 0, 0, 0, 0, H, R, Pi};
Rotate{ {0, 0, 1}, {0, 0, 0}, Pi } { Volume{2}; }
BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; }
// circle arcs at z = 0 and z = H (everything in those planes that is not a straight diameter)
arcs() = Curve In BoundingBox{-R-0.01, -R-0.01, -0.01, R+0.01, R+0.01, 0.01};
arcs() += Curve In BoundingBox{-R-0.01, -R-0.01, H-0.01, R+0.01, R+0.01, H+0.01};
diam() = Curve In BoundingBox{-R-0.01, -0.01, -0.01, R+0.01, 0.01, H+0.01};
arcs() -= diam();
vert() = diam();
vert() -= Curve In BoundingBox{-R-0.01, -0.01, -0.01, R+0.01, 0.01, 0.01};
vert() -= Curve In BoundingBox{-R-0.01, -0.01, H-0.01, R+0.01, 0.01, H+0.01};
Printf("%g arcs, %g vertical edges", #arcs(), #vert());
Transfinite Curve{arcs()} = 21;
Transfinite Curve{vert()} = 16;
// lateral (curved) faces: all faces except the planar caps and the internal diameter plane
side() = Surface{:};
side() -= Surface In BoundingBox{-R-0.01, -R-0.01, -0.01, R+0.01, R+0.01, 0.01};
side() -= Surface In BoundingBox{-R-0.01, -R-0.01, H-0.01, R+0.01, R+0.01, H+0.01};
side() -= Surface In BoundingBox{-R-0.01, -0.01, -0.01, R+0.01, 0.01, H+0.01};
Printf("%g lateral faces", #side());
Transfinite Surface{side()};
Mesh.MeshSizeMax = 0.08;
Physical Volume("roller") = {1, 2};
