// Two overlapping cubes cut into three volumes that share their faces, meshed in 3D: the mesh
// is conforming across the shared faces, and the physical groups name the pieces.
SetFactory("OpenCASCADE");
Mesh.MeshSizeMax = 0.2;
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0.5, 0.5, 0.5, 1, 1, 1};
v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Printf("pieces: %g %g %g", v(0), v(1), v(2));
Physical Volume("first only", 1) = {v(0)};
Physical Volume("both", 2) = {v(1)};
Physical Volume("second only", 3) = {v(2)};
