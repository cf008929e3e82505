// geomesh tutorial 6: the language, for parametric parts.
//
// A pipe flange: a ring with a central bore and a circle of bolt holes. How many holes,
// and how large, are parameters: the script computes everything else. Along the way:
//   - DefineConstant: a parameter with a default that the command line can override
//     (-setnumber holes 8), without editing the script;
//   - Macro ... Return and Call: a named block of statements; here, one round hole;
//   - For ... EndFor loops, If ... EndIf conditions;
//   - lists: built up with += and passed whole where tags are expected;
//   - newp, newc, newcl: the next free tag of each kind, so no tag is ever written twice;
//   - Printf and Sprintf: formatted text, for messages and for names.
//
// Run:  geomesh t6.geo -2                       (6 holes, writes t6.msh)
//       geomesh t6.geo -2 -setnumber holes 8    (8 holes)

// Parameters. Each one is used as a plain variable below; -setnumber NAME VALUE replaces
// its value before the script runs. Min/Max/Step describe its range to a user interface.
DefineConstant[
  holes = {6, Min 3, Max 16, Step 1, Name "Flange/holes"},
  holeRadius = {0.08, Min 0.02, Max 0.15, Name "Flange/hole radius"},
  lc = {0.05, Name "Flange/element size"}
];

outerRadius = 1.0;
boreRadius = 0.35;
boltCircle = 0.7;       // radius of the circle the bolt holes sit on

// Macro RoundHole: a circle of radius r centred at (cx, cy), from four quarter arcs, with
// element size h. A macro sees and sets the caller's variables: it reads cx, cy, r and h,
// and leaves its results in `loop` (the tag of the new curve loop) and `arcs[]`.
Macro RoundHole
  centre = newp;
  Point(centre) = {cx, cy, 0, h};
  Point(centre + 1) = {cx + r, cy, 0, h};
  Point(centre + 2) = {cx, cy + r, 0, h};
  Point(centre + 3) = {cx - r, cy, 0, h};
  Point(centre + 4) = {cx, cy - r, 0, h};
  arcs[] = {};
  For k In {1:4}
    arc = newc;
    Circle(arc) = {centre + k, centre, centre + k % 4 + 1};   // % is the remainder
    arcs[] += arc;
  EndFor
  loop = newcl;
  Curve Loop(loop) = arcs[];
Return

// Would two neighbouring holes leave too little material between them? The gap is the
// distance between their centres, less two radii.
gap = 2 * boltCircle * Sin(Pi / holes) - 2 * holeRadius;
If (gap < 4 * lc)
  Printf("warning: only %.3g between bolt holes; try fewer or smaller holes", gap);
EndIf

// The outer rim and the bore use the same macro: set its inputs, then call it.
cx = 0; cy = 0;
r = outerRadius; h = lc;
Call RoundHole;
rim = loop;
rimArcs[] = arcs[];

r = boreRadius; h = lc;
Call RoundHole;
bore = loop;
boreArcs[] = arcs[];

// The bolt holes, evenly spaced, the first one on the x axis. Each hole's loop joins the
// list of holes of the ring, and each hole gets its own physical group, named by Sprintf.
holeLoops[] = {};
r = holeRadius; h = lc / 2;
For i In {0:holes - 1}
  angle = 2 * Pi * i / holes;
  cx = boltCircle * Cos(angle);
  cy = boltCircle * Sin(angle);
  Call RoundHole;
  holeLoops[] += loop;
  Physical Curve(Sprintf("bolt hole %g", i + 1), 10 + i) = arcs[];
EndFor

// The ring: bounded by the rim, with the bore and every bolt hole as holes. A list stands
// for all its items wherever a list of tags is expected.
Plane Surface(1) = {rim, bore, holeLoops[]};

Physical Surface("flange", 1) = {1};
Physical Curve("rim", 2) = rimArcs[];
Physical Curve("bore", 3) = boreArcs[];

Printf("flange: %g bolt holes of radius %g on a circle of radius %g", holes, holeRadius, boltCircle);
Printf("%g curve loops, %g physical groups", #holeLoops[] + 2, holes + 3);
