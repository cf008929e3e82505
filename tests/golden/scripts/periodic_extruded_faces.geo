// A block extruded with layers whose opposite faces are made periodic after the extrusion: each
// slave face and its curves are meshed after their masters, whatever the order of definition.
Point(1) = {0, 0, 0, 0.5}; Point(2) = {2, 0, 0, 0.5}; Point(3) = {2, 1, 0, 0.5}; Point(4) = {0, 1, 0, 0.5};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Surface{1};
Recombine Surface{1};
Extrude {0, 0, 1} { Surface{1}; Layers{3}; Recombine; }
Periodic Surface {17} = {25} Translate {2, 0, 0};
Periodic Surface {21} = {13} Translate {0, 1, 0};
Periodic Surface {26} = {1} Translate {0, 0, 1};
