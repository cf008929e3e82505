// A square in three partitions (-part 3), each piece in a physical group of its partitions:
// "_part{2}_physical{1}_dim{2}" holds the part of the plate in partition 2.
Mesh.PartitionCreatePhysicals = 1;
Point(1) = {0, 0, 0, 0.1}; Point(2) = {1, 0, 0, 0.1};
Point(3) = {1, 1, 0, 0.1}; Point(4) = {0, 1, 0, 0.1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("plate", 1) = {1};
Physical Curve("rim", 2) = {1, 2, 3, 4};
