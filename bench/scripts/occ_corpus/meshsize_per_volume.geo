// A coarse housing around a finely meshed insert: sizes set per volume with MeshSize{ PointsOf{ Volume{..}; } }.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 2, 1};
Cylinder(2) = {1, 1, 0, 0, 0, 1, 0.4};
v() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Printf("fragments: %g %g", v(0), v(1));
// the housing (the box with a hole) comes first in the result, the untouched insert last;
// the shared points get the insert's size, set last
MeshSize{ PointsOf{ Volume{v(0)}; } } = 0.2;
MeshSize{ PointsOf{ Volume{v(1)}; } } = 0.05;
Physical Volume("insert") = {v(1)};
Physical Volume("housing") = {v(0)};
