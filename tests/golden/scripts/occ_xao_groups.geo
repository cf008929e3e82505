// Merge of an XAO file the reference wrote (its -0 output for a box and a sphere with physical
// groups): its groups become physical groups, named as the file names them.
Merge "occ_reference_groups.xao";
Mesh.MeshSizeMax = 0.5;
