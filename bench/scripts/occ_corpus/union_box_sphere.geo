// Bracket boss: a block unioned with a sphere poking out of its top face.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 2, 2, 1};
Sphere(2) = {1, 1, 1, 0.6};
out[] = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.CharacteristicLengthMin = 0.05;
Mesh.CharacteristicLengthMax = 0.15;
Physical Volume("body") = {out[]};
