// The machined part of the CAD benchmark, built with OpenCASCADE and saved as STEP: a block
// with a through bore and a spherical pocket, a boss, a lofted (B-spline) spout, and fillets.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 4, 2, 1};
Cylinder(2) = {1, 1, -0.5, 0, 0, 2, 0.4};
Cylinder(3) = {3, 1, 1, 0, 0, 0.6, 0.5};
Sphere(4) = {2.2, 0.4, 1.1, 0.45};
Circle(100) = {3, 1, 1.6, 0.5};
Ellipse(101) = {3, 1, 2.2, 0.3, 0.15};
Curve Loop(102) = {100};
Curve Loop(103) = {101};
ThruSections(5) = {102, 103};
u() = BooleanUnion{ Volume{1}; Delete; }{ Volume{3, 5}; Delete; };
d() = BooleanDifference{ Volume{u()}; Delete; }{ Volume{2, 4}; Delete; };
f() = Fillet{d(0)}{1, 3, 5, 7}{0.2};
Save "cad_part.step";
