// A wing segment: a spline-based airfoil-like closed section extruded spanwise.
SetFactory("OpenCASCADE");
c = 1.0; tmax = 0.12; np = 12;
pts[] = {};
// upper surface from trailing edge to leading edge
For i In {0:np}
  x = c * (1 - i/np)^2;
  yt = 5*tmax*c*(0.2969*Sqrt(x/c) - 0.1260*(x/c) - 0.3516*(x/c)^2 + 0.2843*(x/c)^3 - 0.1036*(x/c)^4);
  p = newp; Point(p) = {x, yt + 0.001, 0};
  pts[] += p;
EndFor
// lower surface back to the trailing edge
For i In {1:np-1}
  x = c * (i/np)^2;
  yt = 5*tmax*c*(0.2969*Sqrt(x/c) - 0.1260*(x/c) - 0.3516*(x/c)^2 + 0.2843*(x/c)^3 - 0.1036*(x/c)^4);
  p = newp; Point(p) = {x, -yt - 0.001, 0};
  pts[] += p;
EndFor
Spline(1) = {pts[], pts[0]};
Curve Loop(1) = {1};
Plane Surface(1) = {1};
Extrude {0, 0, 1.5} { Surface{1}; }
Mesh.MeshSizeMax = 0.05;
Mesh.MeshSizeMin = 0.01;
Mesh.MeshSizeFromCurvature = 12;
Physical Volume("wing") = {1};
