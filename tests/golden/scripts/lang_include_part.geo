// Part of lang_include.geo: a rectangle whose width the includer may set first.
part_width = 1;
If (Exists(width))
  part_width = width;
EndIf
p0 = newp;
Point(p0) = {0, 0, 0, 0.1};
Point(p0 + 1) = {part_width, 0, 0, 0.1};
If (!Exists(part_seen))
  part_seen = 1;
  Macro PartReport
    Printf("report: first point %g", p0);
  Return
EndIf
