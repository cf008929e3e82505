// A slab with two square holes between two electrodes (its left and right faces), extruded:
// Homology and Cohomology after meshing, saved as physical groups numbered after 12.
lc = 0.25;
Point(1) = {0, 0, 0, lc}; Point(2) = {5, 0, 0, lc};
Point(3) = {5, 2, 0, lc}; Point(4) = {0, 2, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
loops[] = {1};
For k In {0:1}
  x = 1.2 + 2 * k;
  p = newp;
  Point(p) = {x, 0.7, 0, lc}; Point(p + 1) = {x + 0.6, 0.7, 0, lc};
  Point(p + 2) = {x + 0.6, 1.3, 0, lc}; Point(p + 3) = {x, 1.3, 0, lc};
  l = newl;
  Line(l) = {p, p + 1}; Line(l + 1) = {p + 1, p + 2};
  Line(l + 2) = {p + 2, p + 3}; Line(l + 3) = {p + 3, p};
  loops[] += newcl;
  Curve Loop(newcl) = {l, l + 1, l + 2, l + 3};
EndFor
Plane Surface(1) = loops[];
e[] = Extrude {0, 0, 0.5} { Surface{1}; };

Physical Volume("slab", 1) = {e[1]};
Physical Surface("left", 10) = {e[5]};
Physical Surface("right", 11) = {e[3]};
skin[] = Boundary{ Volume{e[1]}; };
skin[] -= {e[3], e[5]};
Physical Surface("insulated", 12) = skin[];

Homology {{1}, {10, 11}};        // 3 paths: one across, one round each hole
Cohomology(1) {{1}, {10, 11}};   // 3 thick cuts
Homology(2) {{1}, {12}};         // 3 thin cuts
