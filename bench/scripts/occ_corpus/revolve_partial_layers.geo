// Quarter-turn bent duct: a rectangle revolved 90 degrees about the y axis with layers.
SetFactory("OpenCASCADE");
Rectangle(1) = {1, 0, 0, 0.5, 0.3};
Mesh.MeshSizeMax = 0.06;
Extrude { {0, 1, 0}, {0, 0, 0}, Pi/2 } { Surface{1}; Layers{20}; }
Physical Volume("bend") = {1};
