// A MathEval size field inside a cube: 0.02 at its centre, growing with the squared distance.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Field[1] = MathEval;
Field[1].F = "0.02 + 0.2 * ((x - 0.5)^2 + (y - 0.5)^2 + (z - 0.5)^2)";
Background Field = 1;
