// A rectangle from the rotation axis outwards, finely divided along the radius, turned by a
// quarter turn in 20 layers: the faces collapsed on the axis are many small triangles, which
// must not decide alone which way the swept surfaces' faces turn.
Point(1) = {0, 0, 0, 1}; Point(2) = {4.8, 0, 0, 1}; Point(3) = {4.8, 0, 1, 1}; Point(4) = {0, 0, 1, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, 3} = 31; Transfinite Curve{2, 4} = 3;
Transfinite Surface{1}; Recombine Surface{1};
Extrude {{0,0,1},{0,0,0}, Pi/2} { Surface{1}; Layers{20}; Recombine; }
