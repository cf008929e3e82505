// A triangular ramp block (Wedge primitive) with a structured-ish size.
SetFactory("OpenCASCADE");
Wedge(1) = {0, 0, 0, 2, 1, 1.5};
Characteristic Length{ PointsOf{ Volume{1}; } } = 0.1;
Physical Volume("ramp") = {1};
Physical Surface("faces") = Boundary{ Volume{1}; };
