// 200,000 points joined by 199,999 lines, built in For loops: a test of the language
// front end and the built-in kernel (run with -0).
DefineConstant[ n = 200000 ];
For i In {1:n}
  Point(i) = {i / n, Sin(i / 1000), 0, 0.1};
EndFor
For i In {1:n-1}
  Line(i) = {i, i + 1};
EndFor
