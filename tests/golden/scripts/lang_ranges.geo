// Ranges with fractional steps grow by repeated addition and stop as soon as they pass
// the end, in lists and in loops; the loop variable keeps the first value past the end.
a[] = {0:0.3:0.1};
Printf("0:0.3:0.1 has %g values", #a[]);
b[] = {0:1:0.1};
Printf("0:1:0.1 has %g values, the last %.17g", #b[], b[#b[] - 1]);
c[] = {1:0:-0.25};
Printf("1:0:-0.25 has %g values", #c[]);
For t In {0:1:0.1}
EndFor
Printf("t after the loop %.17g", t);
n = 0;
For u In {0:0.3:0.1}
  n++;
EndFor
Printf("%g passes, u ends at %.17g", n, u);
For w In {5:1}
  Printf("never printed");
EndFor
Printf("w after an empty range %g", w);
For i In {1:0:-0.25}
  Printf("down %g", i);
EndFor
Printf("after %g", i);
count = 0;
For (0.1:0.35:0.05)
  count += 1;
EndFor
Printf("anonymous loop ran %g times", count);
x = 3; x++; x--; x += 2;
l[] = {1, 2, 3};
l[1]++;
Printf("%g %g", x, l[1]);
z[] = {};
For i In {1:5}
  If (i % 2 == 0) z[] += i; EndIf
EndFor
Printf("%g even numbers, the second %g", #z[], z[1]);
