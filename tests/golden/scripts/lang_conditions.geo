// If / ElseIf / Else chains, comparisons, logical operators and the ternary operator.
For i In {1:6}
  If (i == 1)
    Printf("%g: one", i);
  ElseIf (i < 3)
    Printf("%g: small", i);
  ElseIf (i == 3 || i == 4)
    Printf("%g: three or four", i);
  Else
    Printf("%g: big", i);
  EndIf
EndFor
x = 0.5;
If (x > 0 && x < 1)
  Printf("inside (0,1)");
EndIf
If (!(x > 1))
  Printf("not above one");
EndIf
y = x > 0.25 ? 10 : 20;
Printf("ternary %g", y);
Printf("nested %g", x < 0 ? -1 : x < 1 ? 0 : 1);
Printf("truth %g %g %g %g", 2 > 1, 2 >= 2, 1 != 1, 3 <= 2);
Printf("logic %g %g %g", 1 && 0, 1 || 0, !0);
Printf("modulo %g %g power %g %g", 7 % 3, -7 % 3, 2^10, 2^-1);
Printf("precedence %g %g", 2 + 3 * 4, -2^2);
If (0)
ElseIf (0)
Else
  Printf("empty branches");
EndIf
