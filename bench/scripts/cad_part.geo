// The STEP part written by cad_part_model.geo, meshed at a uniform size (default 0.02: about
// 190k triangles on planes, cylinders, a sphere, tori and B-spline faces).
DefineConstant[ h = 0.02 ];
Merge "cad_part.step";
Mesh.MeshSizeMin = h;
Mesh.MeshSizeMax = h;
