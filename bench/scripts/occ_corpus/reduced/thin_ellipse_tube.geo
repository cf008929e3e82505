// Reduced 2D: lateral surface of a thin elliptic tube (ellipse 1 x 0.1 extruded); geomesh fails "triangle is inverted or flat".
SetFactory("OpenCASCADE");
Ellipse(1) = {0, 0, 0, 1, 0.1};
Extrude {0, 0, 1} { Curve{1}; }
Mesh.MeshSizeMax = 0.1;
