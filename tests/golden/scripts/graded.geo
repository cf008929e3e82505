// An L-shaped plate graded from size 0.01 at the re-entrant corner to 0.2 at the far corners.
Point(1) = {0, 0, 0, 0.2};
Point(2) = {1, 0, 0, 0.2};
Point(3) = {1, 0.5, 0, 0.05};
Point(4) = {0.5, 0.5, 0, 0.01};
Point(5) = {0.5, 1, 0, 0.05};
Point(6) = {0, 1, 0, 0.2};
For i In {1:5}
  Line(i) = {i, i + 1};
EndFor
Line(6) = {6, 1};
Curve Loop(1) = {1:6};
Plane Surface(1) = {1};
Physical Surface(7) = {1};
