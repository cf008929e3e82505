// Closed cylinder (two caps, four wall patches) in a box: prism layer on all its faces, tetrahedra outside, physical groups; run with -3.
R = 0.3;
H = 0.8;
lc = 0.06;
lcFar = 0.3;
L = 1.2;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
walls[] = {};
tops[] = {};
For c In {1 : 4}
  e[] = Extrude {0, 0, H} { Curve{c}; };
  tops[] += e[0];
  walls[] += e[1];
EndFor
// bottom cap seen from below and top cap seen from above both turn counter-clockwise: normals point out
cl = newcl;
Curve Loop(cl) = {-4, -3, -2, -1};
bottom = news;
Plane Surface(bottom) = {cl};
Curve Loop(cl + 1) = {tops[]};
top = news;
Plane Surface(top) = {cl + 1};
body[] = {bottom, top, walls[]};

out[] = Extrude { Surface{body[]}; Layers{ {1, 1, 1}, {0.005, 0.012, 0.025} }; Recombine; };

// {top, volume, sides...}: a cap has four sides, a wall patch four too
layerTops[] = {};
layer[] = {};
For i In {0 : #body[] - 1}
  layerTops[] += out[6 * i];
  layer[] += out[6 * i + 1];
EndFor

p = newp;
Point(p)     = {-L, -L, -L / 2, lcFar};
Point(p + 1) = { L, -L, -L / 2, lcFar};
Point(p + 2) = { L,  L, -L / 2, lcFar};
Point(p + 3) = {-L,  L, -L / 2, lcFar};
l = newl;
Line(l) = {p, p + 1};
Line(l + 1) = {p + 1, p + 2};
Line(l + 2) = {p + 2, p + 3};
Line(l + 3) = {p + 3, p};
cl = newcl;
Curve Loop(cl) = {l : l + 3};
floor = news;
Plane Surface(floor) = {cl};
e[] = Extrude {0, 0, H + L} { Surface{floor}; };
box = e[1];
Delete { Volume{box}; }
boxFaces[] = {floor, e[0], e[{2 : 5}]};

sl = newsl;
Surface Loop(sl) = {boxFaces[]};
Surface Loop(sl + 1) = {layerTops[]};
air = newv;
Volume(air) = {sl, sl + 1};

Physical Surface("cylinder", 1) = {body[]};
Physical Surface("outer", 2) = {boxFaces[]};
Physical Volume("layer", 3) = {layer[]};
Physical Volume("air", 4) = {air};
