// geomesh tutorial 4: extrusions.
//
// A bent bar, like a crane hook's shank: a straight leg going up, an elbow turning a
// quarter turn, and a straight leg going sideways. Its cross-section, a rectangle with a
// rounded end, is drawn once in the xy plane and swept three times. Extrude returns a list
// of what it created; each sweep starts from the previous one's far face, and the physical
// groups are taken from these lists instead of from tags counted by hand.
//
// With `Layers`, the sweep is meshed in layers: the section's mesh is copied at each layer
// and joined to the next. `Recombine` keeps the layers' sides as quadrangles: quadrangles of
// the section become hexahedra, its triangles become prisms. (Without Recombine, every
// layer would be cut into tetrahedra.)
//
// Run:  geomesh t4.geo -3          (writes t4.msh)

t = 0.6;          // section: width of the rectangle, and diameter of its rounded end
h = 1.0;          // length of the rectangle
x0 = 2.0;         // distance from the section to the elbow's axis
lc = 0.1;

// The section: the rectangle (surface 1) and the half disk at its end (surface 2).
Point(1) = {x0, 0, 0, lc};
Point(2) = {x0 + t, 0, 0, lc};
Point(3) = {x0 + t, h, 0, lc};
Point(4) = {x0, h, 0, lc};
Point(5) = {x0 + t / 2, h, 0, lc};         // centre of the rounded end
Point(6) = {x0 + t / 2, h + t / 2, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Circle(5) = {3, 5, 6};
Circle(6) = {6, 5, 4};
Curve Loop(1) = {1, 2, 3, 4};    Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6};      Plane Surface(2) = {2};

// The rectangle as a 6 x 10 grid of quadrangles (tutorial 3); the half disk stays
// triangular, filled from its boundary, which it shares with the grid along line 3.
Transfinite Curve{1, 3} = 7;
Transfinite Curve{2, 4} = 11;
Transfinite Surface{1};
Recombine Surface{1};

// Leg 1: a translation by (0, 0, 3) in 12 layers.
// For each surface swept, Extrude returns: the far face (the copy of the surface), the
// volume, then one side surface per curve of the surface's boundary, in order. Here:
//   leg1[0] far face of 1, leg1[1] its volume, leg1[2..5] its four sides,
//   leg1[6] far face of 2, leg1[7] its volume, leg1[8..10] its three sides.
leg1[] = Extrude{0, 0, 3}{ Surface{1, 2}; Layers{12}; Recombine; };

// The elbow: a rotation of leg 1's far faces by -Pi/2 about the axis along y through
// (0, 0, 3): Extrude{{axis}, {point on the axis}, angle}. The section sweeps up and over,
// and ends in the plane x = 0, facing -x. Layers count along the arc.
elbow[] = Extrude{{0, 1, 0}, {0, 0, 3}, -Pi / 2}{ Surface{leg1[0], leg1[6]}; Layers{10}; Recombine; };

// Leg 2: a translation along -x, from the elbow's far faces. Layers can also be uneven:
// Layers{{4, 6}, {0.25, 1}} would put 4 layers in the first quarter and 6 in the rest.
leg2[] = Extrude{-2.5, 0, 0}{ Surface{elbow[0], elbow[6]}; Layers{{4, 6}, {0.25, 1}}; Recombine; };

Physical Volume("bar", 1) = {leg1[1], leg1[7], elbow[1], elbow[7], leg2[1], leg2[7]};
Physical Surface("fixed", 2) = {1, 2};                 // the foot of leg 1
Physical Surface("loaded", 3) = {leg2[0], leg2[6]};    // the end of leg 2
Physical Surface("inside", 4) = {elbow[2]};            // the elbow's side that faced y = 0

Printf("volumes %g %g %g %g %g %g", leg1[1], leg1[7], elbow[1], elbow[7], leg2[1], leg2[7]);
