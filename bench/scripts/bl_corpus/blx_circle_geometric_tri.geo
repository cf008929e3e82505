// 2D: triangle layer (no Recombine) around a circle, geometric heights built in a For loop, triangles out to a far circle, physical groups; run with -3.
R = 0.25;
Rfar = 3;
lc = 0.03;
lcFar = 0.4;
n = 10;
first = 0.001;
growth = 1.25;
Point(1) = {0, 0, 0, lc};
Point(2) = {R, 0, 0, lc};
Point(3) = {0, R, 0, lc};
Point(4) = {-R, 0, 0, lc};
Point(5) = {0, -R, 0, lc};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};

counts[] = {};
heights[] = {};
For i In {0 : n - 1}
  counts[] += 1;
  heights[] += first * (growth^(i + 1) - 1) / (growth - 1);  // sum of the first i + 1 cell heights
EndFor

out[] = Extrude { Curve{1:4}; Layers{ counts[], heights[] }; };

tops[] = {out[0], out[4], out[8], out[12]};
layer[] = {out[1], out[5], out[9], out[13]};

p = newp;
Point(p) = {Rfar, 0, 0, lcFar};
Point(p + 1) = {0, Rfar, 0, lcFar};
Point(p + 2) = {-Rfar, 0, 0, lcFar};
Point(p + 3) = {0, -Rfar, 0, lcFar};
c = newl;
Circle(c) = {p, 1, p + 1};
Circle(c + 1) = {p + 1, 1, p + 2};
Circle(c + 2) = {p + 2, 1, p + 3};
Circle(c + 3) = {p + 3, 1, p};
cl = newcl;
Curve Loop(cl) = {c : c + 3};
Curve Loop(cl + 1) = {tops[]};
far = news;
Plane Surface(far) = {cl, cl + 1};

Physical Curve("cylinder", 1) = {1:4};
Physical Curve("farfield", 2) = {c : c + 3};
Physical Surface("layer", 3) = {layer[]};
Physical Surface("outer", 4) = {far};
