// Every OpenCASCADE primitive, with and without its optional arguments: the tags each gets,
// how many entities the model holds after each, and their bounding boxes.
SetFactory("OpenCASCADE");

Macro CountEntities
  nv() = Volume{:}; ns() = Surface{:}; nc() = Curve{:}; np() = Point{:};
  Printf("step %g: %g volumes, %g surfaces, %g curves, %g points", step, #nv(), #ns(), #nc(), #np());
Return

Macro PrintBox
  b() = BoundingBox Volume{t};
  Printf("step %g, volume %g: box %.5g %.5g %.5g  %.5g %.5g %.5g", step, t, b[0], b[1], b[2], b[3], b[4], b[5]);
Return

Box(1) = {0, 0, 0, 1, 2, 3};
t = newv; Sphere(t) = {5, 0, 0, 1};
step = 1; Call PrintBox;  // sphere
t = newv; Sphere(t) = {8, 0, 0, 1, 0, Pi/2, Pi};
step = 2; Call PrintBox;  // quarter ball
step = 3; Call CountEntities;  // after the spheres
Cylinder(30) = {10, 0, 0, 0, 0, 2, 0.5};
Cylinder(31) = {13, 0, 0, 1, 1, 0, 0.5, Pi/2};
t = 31; step = 4; Call PrintBox;  // quarter cylinder
Cone(32) = {0, 10, 0, 0, 0, 1, 1, 0.5};
Cone(33) = {4, 10, 0, 0, 0, 2, 1, 0};
t = 33; step = 5; Call PrintBox;  // pointed cone
Torus(34) = {0, 20, 0, 2, 0.5};
Torus(35) = {8, 20, 0, 2, 0.5, Pi};
Wedge(36) = {0, 30, 0, 1, 1, 1};
Wedge(37) = {3, 30, 0, 2, 1, 1, 0.5};
t = 37; step = 6; Call PrintBox;  // wedge
step = 7; Call CountEntities;  // after the solids
Rectangle(100) = {0, 40, 0, 2, 1};
Rectangle(101) = {3, 40, 0, 2, 1, 0.25};
Disk(102) = {0, 50, 0, 1};
Disk(103) = {3, 50, 0, 1, 0.5};
step = 8; Call CountEntities;  // after the plane shapes
For s In {100:103}
  c() = Boundary{Surface{s};};
  Printf("surface %g is bounded by %g curves, the first %g", s, #c(), c[0]);
EndFor
Printf("next tags: point %g, curve %g, surface %g, volume %g", newp, newl, news, newv);
