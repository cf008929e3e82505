// geomesh tutorial 13: mixed meshes: hexahedra, pyramids and tetrahedra in one part.
//
// A heated plate under a block of air. The plate is thin and flat: a few layers of
// hexahedra through its thickness resolve it with few elements (a structured extrusion, as
// in t3 and t4). The air above is meshed with tetrahedra, free to grade from the plate to a
// coarser far field. Where the air meets the plate's top, the faces are quadrangles, which
// no tetrahedron can share: geomesh stands a pyramid on each quadrangle, apex in the air,
// and fills the rest of the air with tetrahedra around the pyramids. The mesh conforms
// across the whole part: one node per place, each face shared by the elements on both sides.
//
// Run:  geomesh t13.geo -3          (writes t13.msh)

side = 2.0;       // plate side
plate = 0.1;      // plate thickness
air = 0.8;        // height of the air above the plate
cells = 12;       // quadrangles along each side of the plate
far = 0.3;        // element size at the top of the air

// The plate's bottom: a square grid of quadrangles (transfinite and recombined, as in t3).
Point(1) = {0, 0, 0};
Point(2) = {side, 0, 0};
Point(3) = {side, side, 0};
Point(4) = {0, side, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve{1:4} = cells + 1;
Transfinite Surface{1};
Recombine Surface{1};

// The plate: the square extruded in 2 layers; Recombine makes the layers hexahedra.
// plate[0] is its top surface, plate[1] its volume, plate[2..5] its sides.
plate[] = Extrude {0, 0, plate} { Surface{1}; Layers{2}; Recombine; };

// The air: the plate's top extruded upwards without Layers, so the volume is meshed with
// tetrahedra, not swept. Its bottom is the plate's top surface itself, whose mesh is the
// plate's grid of quadrangles: that is where the pyramids go.
box[] = Extrude {0, 0, air} { Surface{plate[0]}; };

// Sizes: the plate's grid sets the size at the bottom of the air (a sixth of the side);
// the top corners of the air ask for a coarser size, and the tetrahedra grade in between.
MeshSize{ PointsOf{ Surface{box[0]}; } } = far;

Printf("plate: volume %g, top %g; air: volume %g, top %g", plate[1], plate[0], box[1], box[0]);

Physical Volume("plate", 1) = {plate[1]};
Physical Volume("air", 2) = {box[1]};
Physical Surface("heated base", 3) = {1};
Physical Surface("plate sides", 4) = {plate[2], plate[3], plate[4], plate[5]};
Physical Surface("air boundary", 5) = {box[0], box[2], box[3], box[4], box[5]};
Physical Surface("interface", 6) = {plate[0]};  // where the pyramids stand

// The mesh: 288 hexahedra in the plate (12 x 12 x 2), one pyramid on each of the 144
// quadrangles of its top, and tetrahedra in the rest of the air; the summary at the end
// counts each kind. To check the whole mesh, save every entity and read the file back:
//   geomesh t13.geo -3 -save_all -o t13.msh && geomesh t13.msh -check
// The check verifies that every face of a pyramid is shared with a hexahedron or a
// tetrahedron, or lies on the boundary, and that no element is inverted.
