// A boundary layer grown from a plate whose thickness a scalar view sets: 1 at the leading
// edge (x = 0), 4 at the trailing edge (x = 2), times the layer heights.
lc = 0.1;
Point(1) = {0, 0, 0, lc};
Point(2) = {2, 0, 0, lc};
Point(3) = {2, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
View "thickness" {
  SQ(0, 0, 0, 2, 0, 0, 2, 1, 0, 0, 1, 0){1, 4, 4, 1};
};
layer[] = Extrude{ Surface{1}; Layers{{1, 1, 1, 1}, {0.005, 0.0115, 0.01995, 0.030935}};
                   Using View[0]; Recombine; };
Physical Volume("layer") = {layer[1]};
Physical Surface("plate") = {1};
