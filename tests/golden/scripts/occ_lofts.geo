// Whole circles and ellipses, lofts through them, fillets and chamfers of OpenCASCADE solids.
SetFactory("OpenCASCADE");

Circle(1) = {0, 0, 0, 0.5};
Curve Loop(1) = 1;
Circle(2) = {0.1, 0.05, 1, 0.1};
Curve Loop(2) = 2;
Circle(3) = {-0.1, -0.1, 2, 0.3};
Curve Loop(3) = 3;
ThruSections(1) = {1:3};
Circle(11) = {2, 0, 0, 0.5};
Curve Loop(11) = 11;
Circle(12) = {2.1, 0.05, 1, 0.1};
Curve Loop(12) = 12;
Circle(13) = {1.9, -0.1, 2, 0.3};
Curve Loop(13) = 13;
Ruled ThruSections(11) = {11:13};
s() = Boundary{ Volume{1}; };
Printf("smooth loft: %g faces", #s());
s() = Boundary{ Volume{11}; };
Printf("ruled loft: %g faces", #s());
c() = Curve{:};
Printf("curves: %g, the last %g", #c(), c[#c()-1]);

Circle(20) = {5, 0, 0, 1, 0, Pi/2};
Ellipse(21) = {8, 0, 0, 2, 1};
Ellipse(22) = {12, 0, 0, 2, 1, 0, Pi};
e() = Boundary{ Curve{22}; };
p() = Point{e[1]};
Printf("half ellipse ends at %g %g", p[0], p[1]);

Box(30) = {0, 10, 0, 1, 1, 1};
Box(31) = {3, 10, 0, 1, 1, 1};
f() = Boundary{ Volume{30}; };
e() = Boundary{ Surface{f[0]}; };
r() = Fillet{30}{e[0], e[1]}{0.1};
Printf("fillet gives volume %g", r[0]);
r() = Chamfer{31}{e[0] + 12}{f[0] + 6}{0.1};
Printf("chamfer gives volume %g", r[0]);
v() = Volume{:}; s() = Surface{:}; p() = Point{:};
Printf("model: %g volumes, %g surfaces, %g points", #v(), #s(), #p());
