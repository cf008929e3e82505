// Mesh.Algorithm 8 (Frontal-Delaunay for quads): the recombined surface is made of
// quadrangles, the other one stays triangular (as in Gmsh, the algorithm alone does not
// recombine).
Mesh.Algorithm = 8;
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc}; Point(4) = {0, 1, 0, lc};
Point(5) = {2, 0, 0, lc}; Point(6) = {2, 1, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4}; Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2}; Plane Surface(2) = {2};
Recombine Surface{1};
