// Union, intersection and difference of OpenCASCADE volumes, with and without deleting their
// arguments: the tags of the results and of what is left.
SetFactory("OpenCASCADE");

Macro Report
  nv() = Volume{:}; ns() = Surface{:}; nc() = Curve{:}; np() = Point{:};
  Printf("step %g -> %g entities, first %g; model: %g volumes, %g surfaces, %g curves, %g points",
         step, #r(), r[0], #nv(), #ns(), #nc(), #np());
Return

Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {0.5, 0.5, 0.5, 1, 1, 1};
r() = BooleanUnion{ Volume{1}; Delete; }{ Volume{2}; Delete; };
step = 1; Call Report;  // union
b() = BoundingBox Volume{r[0]};
Printf("union box %.5g %.5g %.5g %.5g %.5g %.5g", b[0], b[1], b[2], b[3], b[4], b[5]);

Box(10) = {5, 0, 0, 1, 1, 1};
Box(11) = {5.5, 0.5, 0.5, 1, 1, 1};
r() = BooleanDifference{ Volume{10}; }{ Volume{11}; };
step = 2; Call Report;  // difference keeping both
s() = Boundary{ Volume{r[0]}; };
Printf("its %g faces: %g %g %g ... %g", #s(), s[0], s[1], s[2], s[#s() - 1]);

Box(20) = {10, 0, 0, 1, 1, 1};
Sphere(21) = {10.5, 0.5, 1, 0.4};
BooleanIntersection(22) = { Volume{20}; Delete; }{ Volume{21}; Delete; };
r() = Volume{:};
step = 3; Call Report;  // intersection as a statement

Box(30) = {20, 0, 0, 3, 1, 1};
Cylinder(31) = {20.5, 0.5, -1, 0, 0, 3, 0.2};
Cylinder(32) = {21.5, 0.5, -1, 0, 0, 3, 0.2};
Sphere(33) = {22.5, 0.5, 1, 0.3};
r() = BooleanDifference{ Volume{30}; Delete; }{ Volume{31:33}; Delete; };
step = 4; Call Report;  // three holes

Box(40) = {30, 0, 0, 1, 1, 1};
Box(41) = {31, 0, 0, 1, 1, 1};
Box(42) = {30.5, 0.5, 0.5, 1, 1, 1};
r() = BooleanUnion{ Volume{40}; Delete; }{ Volume{41, 42}; Delete; };
step = 5; Call Report;  // union of three, coplanar faces merged
s() = Boundary{ Volume{r[0]}; };
Printf("it has %g faces", #s());
