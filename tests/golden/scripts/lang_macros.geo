// Macros (Macro and Function) called by name, by string and by StrCat, with their
// variables shared with the caller, and recursion bounded by a counter.
Macro Square
  sq = side * side;
  Printf("square of %g is %g", side, sq);
Return
Function Countdown
  If (depth > 0)
    Printf("depth %g", depth);
    depth -= 1;
    Call Countdown;
  EndIf
Return
side = 3; Call Square;
side = 1.5; Call "Square";
depth = 3; Call Countdown;
Printf("depth after %g", depth);
which = "Squ";
side = 4; Call StrCat(which, "are");
For i In {1:3}
  side = i;
  Call Square;
EndFor
Printf("last sq %g", sq);
