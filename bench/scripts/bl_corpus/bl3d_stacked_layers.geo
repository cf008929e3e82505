// A layer grown on the top of another layer: two stacks along the normals of a disc-like patch.
lc = 0.08;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
a[] = Extrude { Surface{1}; Layers{{2}, {0.02}}; Recombine; };
b[] = Extrude { Surface{a[0]}; Layers{{3}, {0.1}}; Recombine; Using Index[1]; };
Physical Volume("inner") = {a[1]};
Physical Volume("outer") = {b[1]};
