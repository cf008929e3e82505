// geomesh tutorial 7: meshing a CAD part.
//
// A plate with a bore, drawn in a CAD program and saved as STEP (part.step, beside this
// script). geomesh reads STEP (.step, .stp), IGES (.iges, .igs) and OpenCASCADE's BREP (.brep)
// files; what it reads becomes entities of the OpenCASCADE kernel, with new tags, exactly as if
// the script had built them. Along the way:
//   - Merge "part.step": read every solid, face, edge and point of the file;
//   - finding entities by where they are (In BoundingBox), since a CAD file has no tags
//     the script could know in advance;
//   - sizes on the points of chosen faces (MeshSize), and a global bound (Mesh.MeshSizeMax);
//   - physical groups on the entities found.
//
// Run:  geomesh t7.geo -3        (writes t7.msh)

// The OpenCASCADE kernel holds what is read; selecting it first makes the queries below
// (BoundingBox, In BoundingBox) look at its entities.
SetFactory("OpenCASCADE");

// Read the part. It is a 2 x 2 x 0.5 plate centred on the z axis, with a bore of radius 0.4
// through it. Its bore is a cylinder: one face whose seam, the line where the face closes on
// itself, the mesher handles like any other boundary curve.
Merge "part.step";

// Which entities did the file hold? Volume{:} and Surface{:} list every tag.
volumes() = Volume{:};
surfaces() = Surface{:};
Printf("read %g volume and %g surfaces", #volumes(), #surfaces());

// Find the faces by place. A small tolerance around each box keeps rounding out of the way.
eps = 1e-3;
bore() = Surface In BoundingBox{-0.4 - eps, -0.4 - eps, -eps, 0.4 + eps, 0.4 + eps, 0.5 + eps};
bottom() = Surface In BoundingBox{-1 - eps, -1 - eps, -eps, 1 + eps, 1 + eps, eps};
top() = Surface In BoundingBox{-1 - eps, -1 - eps, 0.5 - eps, 1 + eps, 1 + eps, 0.5 + eps};
Printf("bore: surface %g; bottom: surface %g; top: surface %g", bore(0), bottom(0), top(0));

// Sizes: 0.2 everywhere at most, 0.05 along the bore, growing away from it.
Mesh.MeshSizeMax = 0.2;
MeshSize{ PointsOf{ Surface{bore()}; } } = 0.05;

// Physical groups: what a solver needs to tell apart.
Physical Volume("plate", 1) = volumes();
Physical Surface("bore", 2) = bore();
Physical Surface("clamped", 3) = bottom();
Physical Surface("loaded", 4) = top();
