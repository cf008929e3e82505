// Untagged Booleans that share or split their inputs' faces, numbered as the reference numbers
// them. Two touching boxes fragmented: the first box's faces 1..6 and curves 1..12 again, the
// second's after them in its own order. Beside two overlapping boxes, the new pieces' faces
// come before those of the piece that kept the first box's tag. A pocket keeps the tags of the
// tool's face it holds as it was, with its curves; a notch keeps none of its tool's (only an
// edge of the tool is left whole). Two squares joined keep the tool's two curves left whole.
SetFactory("OpenCASCADE");

Macro Centers
  Printf("");  // the reference loses a line printed right after its progress line
  Printf(StrCat(name, ": %g pieces"), #r());
  For i In {0:#r()-1}
    Printf("piece %g: %g", i, r(i));
  EndFor
  s() = Surface{:};
  For i In {0:#s()-1}
    bb() = BoundingBox Surface{s(i)};
    Printf("surface %g at %g %g %g", s(i), (bb(0)+bb(3))/2, (bb(1)+bb(4))/2, (bb(2)+bb(5))/2);
  EndFor
  c() = Curve{:}; p() = Point{:};
  Printf("%g curves up to %g, %g points up to %g", #c(), c(#c()-1), #p(), p(#p()-1));
Return

Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
r() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2}; Delete; };
name = "touching boxes"; Call Centers;
Printf("curves of surface 7: %g %g %g %g", Boundary{ Surface{7}; });
Printf("curves of surface 2: %g %g %g %g", Boundary{ Surface{2}; });
Recursive Delete{ Volume{:}; }

Box(1) = {0, 0, 0, 1, 1, 1};
Box(2) = {1, 0, 0, 1, 1, 1};
Box(3) = {1.5, 0, 0, 1, 1, 1};
r() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2, 3}; Delete; };
name = "a box beside two overlapping"; Call Centers;
Recursive Delete{ Volume{:}; }

Box(1) = {0, 0, 0, 3, 3, 3};
Box(2) = {1, 1, 2, 1, 1, 2};
r() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
name = "a pocket"; Call Centers;
Printf("curves of surface 11: %g %g %g %g", Boundary{ Surface{11}; });
Recursive Delete{ Volume{:}; }

Box(1) = {0, 0, 0, 3, 3, 3};
Box(2) = {2.5, 2.5, 1, 1, 1, 1};
r() = BooleanDifference{ Volume{1}; Delete; }{ Volume{2}; Delete; };
name = "a notch"; Call Centers;
Recursive Delete{ Volume{:}; }

Rectangle(1) = {0, 0, 0, 1, 1};
Rectangle(2) = {0.5, 0.5, 0, 1, 1};
r() = BooleanUnion{ Surface{1}; Delete; }{ Surface{2}; Delete; };
name = "two squares joined"; Call Centers;
Printf("curves of surface 1: %g %g %g %g %g %g %g %g", Boundary{ Surface{1}; });
