// MeshAdapt (Mesh.Algorithm 1) on a plate with a round hole, finer around the hole.
Mesh.Algorithm = 1;
Point(1) = {0, 0, 0, 0.08}; Point(2) = {2, 0, 0, 0.08};
Point(3) = {2, 1, 0, 0.08}; Point(4) = {0, 1, 0, 0.08};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Point(5) = {0.6, 0.5, 0, 0.02};
Point(6) = {0.8, 0.5, 0, 0.02}; Point(7) = {0.4, 0.5, 0, 0.02};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 6};
Curve Loop(1) = {1, 2, 3, 4};
Curve Loop(2) = {5, 6};
Plane Surface(1) = {1, 2};
Physical Surface("plate") = {1};
