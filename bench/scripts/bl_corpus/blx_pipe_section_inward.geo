// 2D pipe cross-section: quadrangle layer grown inward from a circle with negative heights, triangles in the core, physical groups; run with -3.
R = 1;
lc = 0.06;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
// counter-clockwise arcs have outward normals: negative heights put the layer inside
out[] = Extrude { Curve{1:4}; Layers{ {1, 1, 1, 1, 1}, {-0.004, -0.01, -0.02, -0.035, -0.06} }; Recombine; };

cl = newcl;
Curve Loop(cl) = {out[0], out[4], out[8], out[12]};
core = news;
Plane Surface(core) = {cl};

Physical Curve("wall", 1) = {1:4};
Physical Surface("layer", 2) = {out[1], out[5], out[9], out[13]};
Physical Surface("core", 3) = {core};
