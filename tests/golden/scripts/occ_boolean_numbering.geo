// Tags after Booleans that delete their arguments: the tools' curves and faces that the
// result keeps as they were keep their tags; the objects' are numbered anew after them.
SetFactory("OpenCASCADE");

// A plate with two holes (2D difference).
Rectangle(1) = {-5, 1, 0, 10, 2};
Rectangle(2) = {-5, -5, 0, 10, 4};
Disk(3) = {0, 0, 0, 20};
BooleanDifference{ Surface{3}; Delete; }{ Surface{1}; Surface{2}; Delete; }
b() = Boundary{ Surface{3}; };
Printf("plate: %g curves, first %g %g, last %g", #b(), b(0), b(1), b(#b() - 1));

// Two overlapping squares joined (2D union).
Rectangle(10) = {30, 0, 0, 1, 1};
Rectangle(11) = {30.5, 0.5, 0, 1, 1};
r() = BooleanUnion{ Surface{10}; Delete; }{ Surface{11}; Delete; };
b() = Boundary{ Surface{r(0)}; };
Printf("union: surface %g, curves %g %g %g %g %g %g %g %g", r(0), b(0), b(1), b(2), b(3), b(4), b(5), b(6), b(7));

// A box with a cavity (3D difference).
Box(20) = {50, 0, 0, 1, 1, 1};
Box(21) = {50.25, 0.25, 0.25, 0.5, 0.5, 0.5};
r() = BooleanDifference{ Volume{20}; Delete; }{ Volume{21}; Delete; };
b() = Boundary{ Volume{r(0)}; };
Printf("cavity: volume %g, faces %g %g ... %g %g", r(0), b(0), b(1), b(10), b(11));

// A spherical pocket through the top of a block: the sphere's curve at its pole, inside the
// block, is numbered anew with the rest.
Box(30) = {70, 0, 0, 2, 2, 1};
Sphere(31) = {71, 1, 1.1, 0.45};
r() = BooleanDifference{ Volume{30}; Delete; }{ Volume{31}; Delete; };
c() = Curve{:};
Printf("pocket: %g curves in the model, from %g to %g", #c(), c(0), c(#c() - 1));
