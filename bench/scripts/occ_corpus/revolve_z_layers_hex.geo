// A quarter annular gasket in hexahedra: a transfinite quad face in the xz-plane revolved Pi/2 about z with Layers.
SetFactory("OpenCASCADE");
Rectangle(1) = {1, 0, 0, 0.4, 0.25};
Rotate{ {1, 0, 0}, {0, 0, 0}, Pi/2 } { Surface{1}; }
Transfinite Curve{1, 3} = 9;
Transfinite Curve{2, 4} = 6;
Transfinite Surface{1};
Recombine Surface{1};
r[] = Extrude{ {0, 0, 1}, {0, 0, 0}, Pi/2 } { Surface{1}; Layers{16}; Recombine; };
Printf("top %g volume %g", r[0], r[1]);
Physical Volume("gasket") = {r[1]};
Physical Surface("end0") = {1};
Physical Surface("end1") = {r[0]};
