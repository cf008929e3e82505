// Legacy-style sizing on a domed cap: Characteristic Length on points, CharacteristicLengthMax and FromCurvature.
SetFactory("OpenCASCADE");
Cylinder(1) = {0, 0, 0, 0, 0, 0.8, 1};
Sphere(2) = {0, 0, 0.8, 1};
Box(3) = {-2, -2, -2, 4, 4, 2.8};
cap() = BooleanDifference{ Volume{2}; Delete; }{ Volume{3}; Delete; };
body() = BooleanUnion{ Volume{1}; Delete; }{ Volume{cap()}; Delete; };
Characteristic Length{ PointsOf{ Volume{body()}; } } = 0.3;
Mesh.CharacteristicLengthMax = 0.15;
Mesh.CharacteristicLengthMin = 0.02;
Mesh.CharacteristicLengthFromCurvature = 1;
Mesh.MinimumElementsPerTwoPi = 30;
Physical Volume("silo") = {body()};
