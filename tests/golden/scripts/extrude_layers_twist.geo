// A structured triangulated square swept up by 2 while turning by an eighth of a turn about
// its centre line (a twist), 8 layers of prisms.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {1, 1, 0, 0.2};
Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
Extrude{{0, 0, 2}, {0, 0, 1}, {0.5, 0.5, 0}, Pi/4}{Surface{1}; Layers{8}; Recombine;}
