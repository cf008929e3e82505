// Homology of a domain naming a physical group that does not exist: the reference logs an
// error and carries on with an empty domain (no group saved); geomesh warns at the statement.
Point(1) = {0, 0, 0, 0.2}; Point(2) = {1, 0, 0, 0.2};
Point(3) = {1, 1, 0, 0.2}; Point(4) = {0, 1, 0, 0.2};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("square", 1) = {1};
Homology {{5}, {}};
Cohomology {{1}, {7}};
