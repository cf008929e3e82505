/* A square plate with two square holes, a clockwise outer loop given with reversed tags,
   and physical groups: only their elements are saved. */
s = 0.05;
Point(1) = {0, 0, 0, s}; Point(2) = {2, 0, 0, s}; Point(3) = {2, 2, 0, s}; Point(4) = {0, 2, 0, s};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};

Point(5) = {0.4, 0.4, 0, s/2}; Point(6) = {0.8, 0.4, 0, s/2};
Point(7) = {0.8, 0.8, 0, s/2}; Point(8) = {0.4, 0.8, 0, s/2};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};

Point(9) = {1.2, 1.1, 0, s}; Point(10) = {1.7, 1.1, 0, s};
Point(11) = {1.7, 1.6, 0, s}; Point(12) = {1.2, 1.6, 0, s};
Line(9) = {9, 10}; Line(10) = {10, 11}; Line(11) = {11, 12}; Line(12) = {12, 9};

Curve Loop(1) = {-4, -3, -2, -1};   // the outer boundary, clockwise
Curve Loop(2) = {5, 6, 7, 8};
Line Loop(3) = {9, 10, 11, 12};     // the old spelling
Plane Surface(1) = {1, 2, 3};

Physical Surface("plate") = {1};
Physical Curve("outer") = {1, 2, 3, 4};
Physical Line("holes", 20) = {5:12};
