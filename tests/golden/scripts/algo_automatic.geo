// Mesh.Algorithm 2 (Automatic): Delaunay on the plane surface, MeshAdapt on the surface
// bounded by a segment and three circle arcs; they share the segment.
Mesh.Algorithm = 2;
lc = 0.1;
Point(1) = {0, 0, 0, lc}; Point(2) = {1, 0, 0, lc}; Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc}; Point(5) = {0.5, 0.5, -0.8, lc}; Point(6) = {0.5, 0.5, -0.6, lc};
Line(1) = {1, 2}; Circle(2) = {2, 5, 3}; Circle(3) = {3, 6, 4}; Circle(4) = {4, 5, 1};
Curve Loop(1) = {1, 2, 3, 4};
Surface(1) = {1};
Point(7) = {0, -1, 0, lc}; Point(8) = {1, -1, 0, lc};
Line(5) = {1, 7}; Line(6) = {7, 8}; Line(7) = {8, 2};
Curve Loop(2) = {5, 6, 7, -1};
Plane Surface(2) = {2};
