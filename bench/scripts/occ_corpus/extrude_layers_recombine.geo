// Structured hex channel: OCC rectangle extruded with Layers and Recombine, transfinite base.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 0.5};
Transfinite Curve{1, 3} = 11;
Transfinite Curve{2, 4} = 6;
Transfinite Surface{1};
Recombine Surface{1};
out[] = Extrude {0, 0, 3} { Surface{1}; Layers{30}; Recombine; };
Physical Volume("channel") = {out[1]};
Physical Surface("in") = {1};
Physical Surface("out") = {out[0]};
