// An OpenCASCADE rectangle extruded with layers: the vertical curves, swept from the corners,
// get one segment per layer, whatever Transfinite Curve asks for them, so the sides are grids.
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 2, 1};
Transfinite Curve {1, 3} = 5;
Transfinite Curve {2, 4} = 3;
Transfinite Surface {1};
Recombine Surface {1};
Extrude {0, 0, 1} { Surface{1}; Layers{4}; Recombine; }
Transfinite Curve {5, 6, 8, 10} = 9;
