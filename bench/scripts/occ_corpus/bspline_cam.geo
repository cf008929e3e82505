// A cam plate: closed BSpline outline with a bore, extruded to 3D.
SetFactory("OpenCASCADE");
lc = 0.08;
N = 10;
For i In {0:N-1}
  th = 2*Pi*i/N;
  rr = 1 + 0.35*Cos(th)^2 + 0.2*Sin(th);
  Point(i+1) = {rr*Cos(th), rr*Sin(th), 0, lc};
EndFor
BSpline(1) = {1:N, 1};
Curve Loop(1) = {1};
Circle(2) = {0, 0, 0, 0.3};
Curve Loop(2) = {2};
Plane Surface(1) = {1, 2};
Extrude {0, 0, 0.3} { Surface{1}; }
Physical Volume("cam") = {1};
