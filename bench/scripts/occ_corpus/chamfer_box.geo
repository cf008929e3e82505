// A cube with its top edges chamfered.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
// edges of the top face (z = 1)
e() = Boundary{ Surface{6}; };
Printf("top edges: %g %g %g %g", e(0), e(1), e(2), e(3));
e() = Abs(e());
Chamfer{1}{e()}{6, 6, 6, 6}{0.15}
Mesh.MeshSizeMax = 0.08;
Physical Volume("part") = {1};
