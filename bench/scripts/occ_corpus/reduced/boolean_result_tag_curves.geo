// Reduced 2D: with an explicit result tag, the ellipse boundary curve 1 gets a new tag (3) in geomesh.
SetFactory("OpenCASCADE");
Disk(1) = {0, 0, 0, 3, 1.5};
Disk(2) = {0.8, 0, 0, 0.4};
BooleanDifference(3) = { Surface{1}; Delete; }{ Surface{2}; Delete; };
Physical Curve("rim") = {1};
Physical Surface("membrane") = {3};
