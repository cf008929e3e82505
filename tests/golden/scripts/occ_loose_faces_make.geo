// Writes occ_loose_faces.brep and .step (read by occ_heal_*.geo): six unit squares on the faces
// of a cube, each with its own points and curves (not sewn). Run once: geomesh occ_loose_faces_make.geo -0
SetFactory("OpenCASCADE");
Macro Face
  p0 = newp; Point(p0) = {c(0), c(1), c(2)}; Point(p0 + 1) = {c(3), c(4), c(5)};
  Point(p0 + 2) = {c(6), c(7), c(8)}; Point(p0 + 3) = {c(9), c(10), c(11)};
  l0 = newc;
  For k In {0:3}
    Line(l0 + k) = {p0 + k, p0 + (k + 1) % 4};
  EndFor
  Curve Loop(newcl) = {l0:l0 + 3};
  Plane Surface(news) = {newcl - 1};
Return
c() = {0,0,0, 1,0,0, 1,1,0, 0,1,0}; Call Face;
c() = {0,0,1, 1,0,1, 1,1,1, 0,1,1}; Call Face;
c() = {0,0,0, 1,0,0, 1,0,1, 0,0,1}; Call Face;
c() = {0,1,0, 1,1,0, 1,1,1, 0,1,1}; Call Face;
c() = {0,0,0, 0,1,0, 0,1,1, 0,0,1}; Call Face;
c() = {1,0,0, 1,1,0, 1,1,1, 1,0,1}; Call Face;
s() = Surface{:}; p() = Point{:};
Printf("%g surfaces, %g points", #s(), #p());
Save "occ_loose_faces.brep";
Save "occ_loose_faces.step";
