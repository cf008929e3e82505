// A structured quadrangle mesh: transfinite curves (a progression and a bump) and a
// recombined transfinite surface with alternating diagonals before recombination.
Point(1) = {0, 0, 0}; Point(2) = {2, 0, 0}; Point(3) = {2, 1, 0}; Point(4) = {0, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1, -3} = 21 Using Progression 1.1;
Transfinite Curve{2, 4} = 11 Using Bump 0.5;
Transfinite Surface{1} Alternate;
Recombine Surface{1};
Physical Surface("plate") = {1};
