// A structured block of hundreds of entities built in loops with the tag counters, then
// meshed in the script itself. The lists of tags are checked as they grow.
n = 12;
lc = 1 / n;
For j In {0:n}
  For i In {0:n}
    pt~{i}~{j} = newp;
    Point(pt~{i}~{j}) = {i * lc, j * lc, 0, lc};
  EndFor
EndFor
Printf("points %g", newp - 1);
horizontal[] = {};
For j In {0:n}
  For i In {0:n - 1}
    l = newl;
    Line(l) = {pt~{i}~{j}, pt~{i + 1}~{j}};
    horizontal[] += l;
  EndFor
EndFor
vertical[] = {};
For i In {0:n}
  For j In {0:n - 1}
    l = newl;
    Line(l) = {pt~{i}~{j}, pt~{i}~{j + 1}};
    vertical[] += l;
  EndFor
EndFor
Printf("lines %g + %g = %g", #horizontal[], #vertical[], newl - 1);
cells = 0;
block[] = {};
For j In {0:n - 1}
  For i In {0:n - 1}
    bottom = horizontal[j * n + i];
    top = horizontal[(j + 1) * n + i];
    left = vertical[i * n + j];
    right = vertical[(i + 1) * n + j];
    Curve Loop(newll) = {bottom, right, -top, -left};
    s = news;
    Plane Surface(s) = {newll - 1};
    block[] += s;
    cells += 1;
  EndFor
EndFor
Printf("surfaces %g, last %g", cells, news - 1);
Physical Surface("block") = block[];
Mesh 2;
Printf("meshed in the script");
