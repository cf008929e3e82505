// A walk through the scripting language; tour.expected holds what it prints.
/* Block comments
   span lines. */
DefineConstant[ n = {4, Min 1, Max 10, Step 1, Name "Parameters/n"} ];
lc = 1 / n;
Printf("lc = %g", lc);

// Operators and precedence
Printf("%g %g %g %g", -2^2, 2^3^2, 7 % 3, 10 - 2 - 3);
Printf("%g %g %g", 1 < 2 && 3 > 2, !1 || 0, 1 ? 2 : 3);

// Lists, ranges, indexing
x[] = {1:3, 10:6:-2};
Printf("#x = %g, x[4] = %g", #x[], x[4]);
y[] = x[{0, 2}];
y[] += {7, 8};
Printf("%g %g %g %g", y[0], y[1], y[2], y[3]);

// Loops and conditionals
sum = 0;
For i In {1:n}
  If (i % 2)
    sum += i;
  Else
    sum -= 1;
  EndIf
EndFor
Printf("sum = %g, i = %g", sum, i);
For (1:2)
  Printf("twice");
EndFor

// Macros
Macro Square
  sq = r * r;
Return
r = 3;
Call Square;
Printf("sq = %g", sq);

// Names built at run time
For k In {1:3}
  v~{k} = k * 10;
EndFor
Printf("%g %g", v_1, v~{3});

// Strings
name = StrCat("mesh", Sprintf("%g", n));
Printf(name);
Printf(StrSub(UpperCase(name), 0, 4));
Printf("%g %g", StrLen(name), StrCmp(name, "mesh"));

// Built-in functions and options
Printf("%g %g %g", Floor(2.7), Round(2.5), Hypot(3, 4));
Mesh.CharacteristicLengthMax = 2 * lc;
Printf("%g", Mesh.MeshSizeMax);

// Geometry
Point(1) = {0, 0, 0, lc};
Point(2) = {1, 0, 0, lc};
Point(3) = {1, 1, 0, lc};
Point(4) = {0, 1, 0, lc};
For c In {1:4}
  Line(c) = {c, c % 4 + 1};
EndFor
Curve Loop(1) = {1:4};
Plane Surface(1) = {1};
Physical Surface("plate") = {1};
Physical Curve("edges") = {1:4};
Printf("%g %g %g", newp, newl, newreg);
