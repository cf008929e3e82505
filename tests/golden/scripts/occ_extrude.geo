// Extrusions and revolutions of OpenCASCADE points, curves and surfaces: the lists they
// return (top, swept entity, lateral entities) and the tags they give.
SetFactory("OpenCASCADE");

Macro Report
  Printf("step %g: %g entities", step, #r());
  For i In {0:#r()-1}
    Printf("%g", r[i]);
  EndFor
Return

Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Line(1) = {1, 2};
r() = Extrude{0, 1, 0}{ Curve{1}; };
step = 1; Call Report;  // a line swept
r() = Extrude{0, 0, 1}{ Surface{r[1]}; };
step = 2; Call Report;  // its square swept
r() = Extrude{{0, 0, 1}, {0, 0, 0}, Pi/2}{ Point{2}; };
step = 3; Call Report;  // a point turned

Rectangle(10) = {5, 0, 0, 2, 1};
Disk(11) = {10, 0, 0, 1};
r() = Extrude{0, 0, 1}{ Surface{10, 11}; };
step = 4; Call Report;  // two plates raised

Rectangle(20) = {1, 5, 0, 1, 1};
r() = Extrude{{0, 1, 0}, {0, 5, 0}, Pi/2}{ Surface{20}; };
step = 5; Call Report;  // a plate turned
v() = Volume{:};
Printf("volumes now: %g, the last %g", #v(), v[#v()-1]);
