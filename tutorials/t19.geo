// geomesh tutorial 19: boundary layers: prisms grown from a wall.
//
// One tube of a heat exchanger, crossing a duct from floor to ceiling, with air flowing
// past it along x. What a flow solver needs at the tube is a stack of thin cells on its wall:
// the velocity and the temperature change fastest there, across a few hundredths of the
// diameter, while along the wall and away from it coarse cells do. Tetrahedra small enough
// across the wall would be small in every direction; prisms can be thin across it and wide
// along it. Here the tube's wall is extruded along its own normals, in layers whose heights
// grow geometrically, and the rest of the duct is filled with tetrahedra beyond the layer.
//
// Run:  geomesh t19.geo -3                             (writes t19.msh)
//       geomesh t19.geo -3 -setnumber layers 10        (a thicker layer, in 10 cells)

// The layer's law: the first cell's height on the wall, the ratio between one cell's height
// and the next one's, and the number of cells. A solver's wall treatment dictates the first
// height (a y+ near 1 for a resolved wall); the ratio stays below about 1.3 so that
// neighbouring cells stay alike.
DefineConstant[
  firstHeight = {0.004, Min 0.0005, Max 0.05, Name "Layer/first cell height"},
  ratio = {1.25, Min 1, Max 2, Name "Layer/growth ratio"},
  layers = {6, Min 1, Max 20, Step 1, Name "Layer/number of cells"}
];

R = 0.5;          // tube radius
H = 1.0;          // duct height: the tube spans it
W = 3.0;          // duct width (y), a tube pitch: the sides are halfway to the next tubes
upstream = 3.0;   // duct length before the tube's axis
downstream = 6.0; // and after it
lcTube = 0.08;    // element size on the tube
lcFar = 0.3;      // element size at the duct's ends

// The tube's wall: four quarter circles on the floor, each swept up to the ceiling (t4).
// Each sweep returns its top curve, then the surface: wall[] gathers the four surfaces.
Point(1) = {0, 0, 0, lcTube};
Point(2) = {R, 0, 0, lcTube};
Point(3) = {0, R, 0, lcTube};
Point(4) = {-R, 0, 0, lcTube};
Point(5) = {0, -R, 0, lcTube};
For k In {1 : 4}
  Circle(k) = {k + 1, 1, k % 4 + 2};
EndFor
wall[] = {};
For k In {1 : 4}
  e[] = Extrude {0, 0, H} { Curve{k}; };
  wall[] += e[1];
EndFor

// The heights of the layers, built in a loop. Along the normals, the second list of Layers
// holds the distances from the wall to the top of each stack of cells (not fractions of one,
// as in a translation): heights[] = h1, h1 + h1 r, h1 + h1 r + h1 r^2, ... The first list
// says how many cells each stack has: one each, so each height is one cell's top.
cells[] = {};
heights[] = {};
h = firstHeight;
top = 0;
For i In {1 : layers}
  top += h;
  cells[] += 1;
  heights[] += top;
  h *= ratio;
EndFor
Printf("layer: %g cells, first %g, last %g, thickness %g", layers, firstHeight, h / ratio, top);

// The boundary layer. Extrude without a direction moves every node of the surfaces along the
// surfaces' normal there, by the heights of Layers; Recombine keeps the cells as prisms
// (triangles of the wall stacked into prisms). A surface made by sweeping a counterclockwise
// arc upwards has its normal pointing away from the axis, into the air: positive heights
// grow the layer outwards; negative ones would grow it the other way.
//
// For each surface, the list returned is: the layer's top surface (the wall's copy at the
// full height), the layer's volume, then one side surface per curve of the wall's boundary,
// in its order. A wall patch is bounded by its arc on the floor, a vertical line, its arc on
// the ceiling and another line, so for patch i:
//   bl[6*i] top, bl[6*i+1] volume, bl[6*i+2] side on the floor, bl[6*i+4] side on the
//   ceiling; bl[6*i+3] and bl[6*i+5] are shared with the neighbouring patches' layers.
// The sides on the floor and the ceiling are flat: the normal of an upright wall is
// horizontal, so the layer's foot lies in the floor, an annulus around the tube.
bl[] = Extrude { Surface{wall[]}; Layers{cells[], heights[]}; Recombine; };

layerTops[] = {};
layerVolumes[] = {};
floorRing[] = {};
ceilingRing[] = {};
floorEdge[] = {};
ceilingEdge[] = {};
For i In {0 : #wall[] - 1}
  layerTops[] += bl[6 * i];
  layerVolumes[] += bl[6 * i + 1];
  floorRing[] += bl[6 * i + 2];
  ceilingRing[] += bl[6 * i + 4];
  // The annulus' outer arc, where the duct's floor begins: the third curve of its boundary
  // (it is bounded like the wall patch: inner arc, side, outer arc, side).
  b[] = Boundary{ Surface{bl[6 * i + 2]}; };
  floorEdge[] += Abs(b[2]);
  b[] = Boundary{ Surface{bl[6 * i + 4]}; };
  ceilingEdge[] += Abs(b[2]);
EndFor

// The duct: floor and ceiling are rectangles with a hole, the layer's outer edge; inlet,
// outlet and the two sides are plain rectangles.
x0 = -upstream; x1 = downstream; y0 = -W / 2; y1 = W / 2;
p = newp;
Point(p) = {x0, y0, 0, lcFar};     Point(p + 1) = {x1, y0, 0, lcFar};
Point(p + 2) = {x1, y1, 0, lcFar}; Point(p + 3) = {x0, y1, 0, lcFar};
Point(p + 4) = {x0, y0, H, lcFar}; Point(p + 5) = {x1, y0, H, lcFar};
Point(p + 6) = {x1, y1, H, lcFar}; Point(p + 7) = {x0, y1, H, lcFar};
l = newc;
For k In {0 : 3}
  Line(l + k) = {p + k, p + (k + 1) % 4};              // floor edges
  Line(l + 4 + k) = {p + 4 + k, p + 4 + (k + 1) % 4};  // ceiling edges
  Line(l + 8 + k) = {p + k, p + 4 + k};                // uprights
EndFor
cl = newcl;
Curve Loop(cl) = {l : l + 3};                          Curve Loop(cl + 1) = {floorEdge[]};
Curve Loop(cl + 2) = {l + 4 : l + 7};                  Curve Loop(cl + 3) = {ceilingEdge[]};
Curve Loop(cl + 4) = {l + 3, l + 8, -(l + 7), -(l + 11)};   // inlet, x = x0
Curve Loop(cl + 5) = {l + 1, l + 10, -(l + 5), -(l + 9)};   // outlet, x = x1
Curve Loop(cl + 6) = {l, l + 9, -(l + 4), -(l + 8)};        // side y = y0
Curve Loop(cl + 7) = {l + 2, l + 11, -(l + 6), -(l + 10)};  // side y = y1
s = news;
Plane Surface(s) = {cl, cl + 1};       // floor, around the layer's foot
Plane Surface(s + 1) = {cl + 2, cl + 3};
For k In {2 : 5}
  Plane Surface(s + k) = {cl + k + 2};
EndFor

// The air beyond the layer: its boundary is the duct's six faces, the floor and ceiling
// around the layer, and the layer's top surfaces. Meshed with tetrahedra, which meet the
// layer's top triangles face to face.
sl = newsl;
Surface Loop(sl) = {s : s + 5, layerTops[]};
core = newv;
Volume(core) = {sl};

// What a solver reads: the tube's wall (no slip, heat flux), the inlet and outlet, the
// duct's walls (floor and ceiling with the layer's feet, and the sides, taken as slip walls
// here), and the air in two parts, so that the layer's cells can be told apart. The layer's
// top surfaces and the sides between its patches lie inside the air: they belong to no
// group, and geomesh names them when it leaves them out of the file.
Physical Surface("wall", 1) = {wall[]};
Physical Surface("inlet", 2) = {s + 2};
Physical Surface("outlet", 3) = {s + 3};
Physical Surface("duct", 4) = {s, s + 1, s + 4, s + 5, floorRing[], ceilingRing[]};
Physical Volume("fluid-layer", 5) = {layerVolumes[]};
Physical Volume("fluid-core", 6) = {core};

// In two dimensions the same statement grows quadrangles from curves: for a section of the
// tube in the plane z = 0, with its circle made of arcs 1 to 4,
//   ring[] = Extrude { Curve{1 : 4}; Layers{cells[], heights[]}; Recombine; };
// returns, for each arc, the layer's top curve, its surface of quadrangles, then the two
// short sides; a Plane Surface between a far boundary and the top curves ring[4*i] is then
// meshed with triangles. A curve's normal there is its tangent turned a quarter turn
// clockwise: a counterclockwise circle grows outwards.
//
// The surfaces (or curves) extruded along normals with the same index, 0 unless told, share
// their normals at the nodes they share, so the layer runs on unbroken across the seams
// between the tube's patches. For a second body with a layer of its own, add
// `Using Index[1];` inside the braces of its Extrude: the normals of each index are computed
// apart, and the two layers never mix.
