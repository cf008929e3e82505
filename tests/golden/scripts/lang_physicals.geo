// Physical groups by name and tag, appended and removed, and the tags newreg hands out.
lc = 0.5;
For i In {0:3}
  Point(newp) = {i, 0, 0, lc};
EndFor
For i In {1:3}
  Line(newl) = {i, i + 1};
EndFor
Physical Point("ends") = {1, 4};
Physical Curve("left half") = {1};
Physical Curve("left half") += {2};
Physical Curve(7) = {3};
Physical Curve("named", 20) = {1, 2, 3};
Physical Curve(20) -= {2};
Printf("next region %g, next curve %g", newreg, newl);
pc[] = Physical Curve{:};
Printf("physical curves: %g", #pc[]);
members[] = Physical Curve{20};
Printf("group 20 holds %g curves", #members[]);
Delete Physicals;
Physical Point(5) = {2};
Printf("after Delete Physicals: next region %g", newreg);
