// An extruded, recombined plate with a round hole: 20-node hexahedra and 8-node quadrangles
// with Mesh.SecondOrderIncomplete, their edge nodes on the hole's arcs.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {2, 0, 0, 0.2}; Point(3) = {2, 1, 0, 0.2};
Point(4) = {0, 1, 0, 0.2}; Point(5) = {1, 0.5, 0, 0.1}; Point(6) = {1.3, 0.5, 0, 0.1};
Point(7) = {1, 0.8, 0, 0.1}; Point(8) = {0.7, 0.5, 0, 0.1}; Point(9) = {1, 0.2, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Circle(5) = {6, 5, 7}; Circle(6) = {7, 5, 8}; Circle(7) = {8, 5, 9}; Circle(8) = {9, 5, 6};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(1) = {1, 2};
Recombine Surface{1};
Extrude{0, 0, 0.3}{ Surface{1}; Layers{2}; Recombine; }
Mesh.ElementOrder = 2;
Mesh.SecondOrderIncomplete = 1;
