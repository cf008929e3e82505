// A square beside the z axis turned four times by a quarter turn, each top extruded again: the
// last top closes the turn on surface 1, so the chain of copies is cut at surface 1.
Point(1) = {1, 0, 0, 0.5}; Point(2) = {2, 0, 0, 0.5}; Point(3) = {2, 0, 1, 0.5}; Point(4) = {1, 0, 1, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1}; Recombine Surface{1};
a[] = Extrude {{0,0,1},{0,0,0}, Pi/2} { Surface{1}; Layers{3}; Recombine; };
b[] = Extrude {{0,0,1},{0,0,0}, Pi/2} { Surface{a[0]}; Layers{3}; Recombine; };
c[] = Extrude {{0,0,1},{0,0,0}, Pi/2} { Surface{b[0]}; Layers{3}; Recombine; };
d[] = Extrude {{0,0,1},{0,0,0}, Pi/2} { Surface{c[0]}; Layers{3}; Recombine; };
