// A solid round bar (cylinder along z) with inlet/outlet/wall groups.
SetFactory("OpenCASCADE");

r = 0.5;
len = 3;
Cylinder(1) = {0, 0, 0, 0, 0, len, r};

Mesh.CharacteristicLengthMax = 0.12;

Physical Volume("fluid") = {1};
Physical Surface("wall") = {1};
Physical Surface("inlet") = {3};
Physical Surface("outlet") = {2};
