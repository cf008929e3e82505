// BooleanFragments of several volumes, of plane surfaces, and of shapes of mixed dimensions:
// the lists they return and the tags of every piece.
SetFactory("OpenCASCADE");

Macro Report
  Printf("step %g: %g pieces", step, #r());
  For i In {0:#r()-1}
    Printf("piece %g: %g", i, r[i]);
  EndFor
  nv() = Volume{:}; ns() = Surface{:}; nc() = Curve{:}; np() = Point{:};
  Printf("model: %g volumes, %g surfaces, %g curves, %g points", #nv(), #ns(), #nc(), #np());
Return

// A slab with four balls sunk into its top and one ball away from it.
Box(1) = {0, 0, 0, 4, 1, 1};
For k In {0:3}
  Sphere(2 + k) = {0.5 + k, 0.5, 1, 0.3};
EndFor
Sphere(6) = {10, 0, 0, 0.5};
r() = BooleanFragments{ Volume{1}; Delete; }{ Volume{2:6}; Delete; };
step = 1; Call Report;  // slab and balls

// Overlapping plates with a hole-to-be.
Rectangle(100) = {0, 5, 0, 2, 1};
Rectangle(101) = {1, 5.5, 0, 2, 1};
Disk(102) = {0.5, 5.5, 0, 0.3};
r() = BooleanFragments{ Surface{100}; Delete; }{ Surface{101, 102}; Delete; };
step = 2; Call Report;  // plates

// A cube cut in two by a plate larger than it.
Box(50) = {0, 10, 0, 1, 1, 1};
Rectangle(150) = {-0.5, 9.5, 0.5, 2, 2};
r() = BooleanFragments{ Volume{50}; Delete; }{ Surface{150}; Delete; };
step = 3; Call Report;  // cube and plate
