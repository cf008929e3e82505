// geomesh tutorial 10: meshes for parallel solvers.
//
// A cold plate: a slab of metal with three coolant channels drilled through it, meshed with
// tetrahedra and split into four partitions, one per process of an MPI solver. Each process
// reads the elements of its partition, and where two partitions meet it needs to know which
// nodes it shares and with whom: the partitioned mesh file says it.
//
// `PartitionMesh n;` splits the mesh that exists when it runs: every tetrahedron goes to one
// of n partitions, chosen by METIS so that the partitions hold nearly the same number of
// elements and as few faces as possible lie between two of them (each such face is data
// the solver sends between processes). The triangles of the surfaces, the lines and the
// points then follow the tetrahedra they touch. On the command line, `-part n` does the same
// after meshing: `geomesh t10.geo -3 -part 8` makes eight partitions instead.
//
// The MSH 4.1 file of a partitioned mesh keeps the model's entities and adds, for each
// partition, the pieces of every entity that lie in it ($PartitionedEntities): piece 12 is
// "the part of volume 1 in partition 3", piece 30 "the surface between partitions 1 and 3
// inside volume 1". Each piece knows its parent entity, its partitions and the pieces that
// bound it, so a solver can rebuild each partition's boundary; the nodes and elements are
// written under the pieces. MSH 2.2 files (`-format msh22`) carry the partitions as extra
// tags of each element instead.
//
// Run:  geomesh t10.geo -3                 (writes t10.msh, in 4 partitions)
//       geomesh t10.geo -3 -part_split     (one file per partition: t10_1.msh ... t10_4.msh)
//       geomesh t10.msh -o t10.vtu         (any mesh file to another format, e.g. for ParaView)

lc = 0.15;

// The slab's face in the xy plane: a 4 x 2 rectangle with three holes of radius 0.3.
Point(1) = {0, 0, 0, lc};
Point(2) = {4, 0, 0, lc};
Point(3) = {4, 2, 0, lc};
Point(4) = {0, 2, 0, lc};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
holes[] = {};
For i In {1:3}
  c = newp; Point(c) = {i, 1, 0, lc / 2};
  arcs[] = {};
  For k In {0:3}
    p~{k} = newp; Point(p~{k}) = {i + 0.3 * Cos(k * Pi / 2), 1 + 0.3 * Sin(k * Pi / 2), 0, lc / 2};
  EndFor
  For k In {0:3}
    a = newc; Circle(a) = {p~{k}, c, p~{(k + 1) % 4}};
    arcs[] += a;
  EndFor
  loop = newcl; Curve Loop(loop) = {arcs[]};
  holes[] += loop;
EndFor
Plane Surface(1) = {1, holes[]};

// Swept one unit along z: the slab, its far face, and its side faces (the four outer sides,
// then four quarter-cylinders per channel).
slab[] = Extrude {0, 0, 1} { Surface{1}; };

Physical Volume("plate", 1) = {slab[1]};
Physical Surface("base", 2) = {1};
Physical Surface("top", 3) = {slab[0]};
Physical Surface("sides", 4) = {slab[{2:5}]};
Physical Surface("channels", 5) = {slab[{6:17}]};

// How METIS splits: 1 recursive bisection (the default), 2 k-way, which is faster for many
// partitions. Mesh.PartitionCreatePhysicals would add a physical group per partition (named
// "_part{2}_physical{1}_dim{3}"); here the pieces stay in the groups of their parents.
Mesh.MetisAlgorithm = 2;
Mesh.PartitionCreatePhysicals = 0;

Mesh 3;
PartitionMesh 4;
