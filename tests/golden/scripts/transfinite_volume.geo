// A structured block of hexahedra: a skewed six-faced volume whose faces are transfinite
// grids of quadrangles, filled by Transfinite Volume (corners found from the shape).
Point(1) = {0, 0, 0};
Point(2) = {2, 0, 0};
Point(3) = {2.2, 1, 0};
Point(4) = {0, 1.2, 0};
Point(5) = {0, 0, 1};
Point(6) = {2, 0.1, 1.3};
Point(7) = {2.1, 1, 1.2};
Point(8) = {0.1, 1.1, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {1, 2, 3, 4};    Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8};    Surface(2) = {2};
Curve Loop(3) = {1, 10, -5, -9}; Surface(3) = {3};
Curve Loop(4) = {2, 11, -6, -10}; Surface(4) = {4};
Curve Loop(5) = {3, 12, -7, -11}; Surface(5) = {5};
Curve Loop(6) = {4, 9, -8, -12}; Surface(6) = {6};
Surface Loop(1) = {1:6};
Volume(1) = {1};
Transfinite Curve{1, 3, 5, 7} = 11 Using Progression 1.1;
Transfinite Curve{2, 4, 6, 8} = 7;
Transfinite Curve{9:12} = 5;
Transfinite Surface{1:6};
Recombine Surface{1:6};
Transfinite Volume{1};
Physical Volume("block") = {1};
