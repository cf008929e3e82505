// A slab whose front and back faces are periodic, after its two long edges were declared
// periodic the other way round (the back edge a copy of the front one): both declarations
// tie the same curves, so the mesh is made, the faces matching node for node.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {2, 0, 0, 0.2};
Point(3) = {2, 1, 0, 0.2};
Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Periodic Curve{3} = {-1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
slab[] = Extrude {0, 0, 0.5} { Surface{1}; Layers{2}; };
// slab[2] is swept from curve 1 (y = 0), slab[4] from curve 3 (y = 1).
Periodic Surface{slab[2]} = {slab[4]} Translate {0, -1, 0};
