// Prism boundary layer grown outward from a built-in sphere (8 patches), extruded along normals; run with -3.
lc = 0.15;
R = 1;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Point(6) = {0, 0, R, lc};
Point(7) = {0, 0, -R, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Circle(5) = {3, 1, 6};
Circle(6) = {6, 1, 5};
Circle(7) = {5, 1, 7};
Circle(8) = {7, 1, 3};
Circle(9) = {2, 1, 7};
Circle(10) = {7, 1, 4};
Circle(11) = {4, 1, 6};
Circle(12) = {6, 1, 2};
// loops oriented so that every patch normal points away from the centre
Curve Loop(21) = {10, -8, -2};  Surface(31) = {21};
Curve Loop(22) = {-7, -3, -10}; Surface(32) = {22};
Curve Loop(23) = {-1, 9, 8};    Surface(33) = {23};
Curve Loop(24) = {-5, 2, 11};   Surface(34) = {24};
Curve Loop(25) = {1, 12, 5};    Surface(35) = {25};
Curve Loop(26) = {-6, -11, 3};  Surface(36) = {26};
Curve Loop(27) = {-9, -4, 7};   Surface(37) = {27};
Curve Loop(28) = {6, -12, 4};   Surface(38) = {28};

// four layers, total thickness 0.1
out[] = Extrude {
  Surface{31:38};
  Layers{ {1, 1, 1, 1}, {0.01, 0.03, 0.06, 0.1} };
  Recombine;
};
