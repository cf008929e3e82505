// Names built at run time with ~{}, lists of them, and the functions that test variables.
For i In {1:3}
  width~{i} = i * 0.5;
  For j In {1:2}
    cell~{i}~{j} = 10 * i + j;
  EndFor
EndFor
Printf("%g %g %g", width_1, width~{2}, width_3);
Printf("%g %g", cell_2_1, cell~{3}~{2});
Printf("exists %g %g %g", Exists(width_2), Exists(width_9), Exists(cell~{1}~{2}));
Printf("value %g %g", GetValue("How fine?", 0.2), GetNumber("Nothing", 42));
Mesh.MeshSizeMax = 0.3;
Printf("option %g %g", Mesh.MeshSizeMax, GetNumber("Mesh.MeshSizeMax"));
Geometry.Tolerance = 1e-6;
Printf("%g", Geometry.Tolerance);
Mesh.CharacteristicLengthMin = 0.01;
Printf("old name %g new name %g", Mesh.CharacteristicLengthMin, Mesh.MeshSizeMin);
Mesh.MinimumCirclePoints = 12;
Printf("circle nodes %g", Mesh.MinCircleNodes);
Printf("version %g.%g", GMSH_MAJOR_VERSION, GMSH_MINOR_VERSION);
Printf("pi %.6f", Pi);
