// Hemispherical dome with a geometric layer (first height and ratio) whose Layers lists are built in a For loop; run with -3.
R = 1;
lc = 0.1;
n = 8;       // number of layers
h1 = 0.002;  // first cell height
ratio = 1.3;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Point(6) = {0, 0, R, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Circle(5) = {2, 1, 6};
Circle(6) = {3, 1, 6};
Circle(7) = {4, 1, 6};
Circle(8) = {5, 1, 6};
Curve Loop(1) = {1, 6, -5}; Surface(1) = {1};
Curve Loop(2) = {2, 7, -6}; Surface(2) = {2};
Curve Loop(3) = {3, 8, -7}; Surface(3) = {3};
Curve Loop(4) = {4, 5, -8}; Surface(4) = {4};

one[] = {};
heights[] = {};
h = h1;
total = 0;
For i In {1 : n}
  total += h;
  one[] += 1;
  heights[] += total;
  h *= ratio;
EndFor
Printf("layer thickness %g", total);

out[] = Extrude { Surface{1:4}; Layers{ one[], heights[] }; Recombine; };
