// Reduced: indexing a list with a list of indices, f({1:3}), is rejected by geomesh.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Box(3) = {2, 0, 0, 1, 1, 1};
f() = {1, 2, 3};
Physical Volume("rest") = {f({1:2})};
