// The field names and options of older scripts: Attractor with NodesList, EdgesList and
// NNodesByEdge, Threshold with IField, LcMin and LcMax.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {2, 0, 0, 0.2};
Point(3) = {2, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Point(5) = {1.5, 0.5, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Field[1] = Attractor;
Field[1].NodesList = {5};
Field[1].EdgesList = {4};
Field[1].NNodesByEdge = 50;
Field[2] = Threshold;
Field[2].IField = 1;
Field[2].LcMin = 0.02;
Field[2].LcMax = 0.2;
Field[2].DistMin = 0.05;
Field[2].DistMax = 0.5;
Background Field = 2;
