// Nested loops with ranges and steps, loop variables after the loop, and a grid of
// hundreds of points built with counters.
n = 0;
For i In {1:10}
  For j In {0:1:0.25}
    n += 1;
  EndFor
EndFor
Printf("inner iterations: %g, i after loop: %g, j after loop: %g", n, i, j);
For k In {10:1:-3}
  Printf("down %g", k);
EndFor
Printf("k after: %g", k);
For (1:3)
  n -= 1;
EndFor
Printf("n = %g", n);
s = 0;
For x In {0.1:0.5:0.1}
  s += x;
EndFor
Printf("sum %.10g last %g", s, x);
lc = 0.1;
first = newp;
For r In {0:19}
  For c In {0:19}
    Point(newp) = {c * lc, r * lc, 0, lc};
  EndFor
EndFor
Printf("points %g..%g, next %g", first, newp - 1, newp);
