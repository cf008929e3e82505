// A bow-tie: curves 2 and 4 cross. The mesher refuses it, naming the surface and the curve.
Point(1) = {0,0,0,0.1}; Point(2) = {3,0,0,0.1}; Point(3) = {0,1,0,0.1}; Point(4) = {1,2,0,0.1};
Line(1) = {1,2}; Line(2) = {2,3}; Line(3) = {3,4}; Line(4) = {4,1};
Curve Loop(1) = {1,2,3,4};
Plane Surface(1) = {1};
