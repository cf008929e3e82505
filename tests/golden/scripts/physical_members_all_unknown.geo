// A physical group whose every member is missing from the model holds no entity: the mesh
// file then keeps every element, as when there is no group, and still names the group.
Point(1) = {0, 0, 0, 0.25};
Point(2) = {1, 0, 0, 0.25};
Line(1) = {1, 2};
s[] = Extrude {0, 1, 0} { Curve{1}; Layers{4}; Recombine; };
Physical Surface("plate", 1) = {1};  // the extruded surface is s[1] = 5, not 1
