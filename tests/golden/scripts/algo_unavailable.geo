// Algorithms geomesh does not have fall back to Frontal-Delaunay with a warning: packing of
// parallelograms (9) asked for by Mesh.Algorithm, and 4, which is no 2D algorithm, for surface 2.
Mesh.Algorithm = 9;
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {2, 0, 0, lc}; Point(6) = {2, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
MeshAlgorithm Surface{2} = 4;
