// A filling whose loop is plane, cut by plane faces inside it: the cut makes holes.
SetFactory("OpenCASCADE");
Point(1) = {0, 0, 0};
Point(2) = {200, 0, 0};
Point(3) = {0, 200, 0};
Point(4) = {-200, 0, 0};
Point(5) = {0, -200, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1:4};
Surface(1) = {1};
Rectangle(2) = {-50, 1.1, 0, 99.9, 3.8};
Rectangle(3) = {-50, -5, 0, 100, 4};
r() = BooleanDifference{ Surface{1}; Delete; }{ Surface{2, 3}; Delete; };
b() = Boundary{ Surface{r(0)}; };
Printf("the cut filling: %g surface, bounded by %g curves", #r(), #b());
