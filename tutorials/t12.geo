// t12: loops and cuts for a magnetic field problem: homology and cohomology of the air
// around a conducting ring.
//
// A current in a ring makes a magnetic field in the air around it. Where no current flows,
// the field is the gradient of a scalar potential, which is much cheaper to solve for than a
// vector one, but only if every closed loop in the region can be shrunk to a point: the
// field's circulation round the ring equals the current, so a potential that is single
// valued cannot exist in the air, which the ring threads like a doughnut's hole. The fix is a
// cut: a surface that spans the hole, across which the potential jumps by the current. The
// mesh has to be given the loops and the cuts, and finding them by hand on a real part (a
// motor, a transformer with several windings) is error-prone: geomesh computes them.
//
// Homology counts and finds the independent loops (and shells, and paths between given
// parts of a boundary) that cannot be shrunk away in a region; cohomology finds their duals,
// the cuts. Both are computed on the mesh, exactly, over the integers, once it is made.

SetFactory("OpenCASCADE");

DefineConstant[ size = 0.3 ];

// The ring: a square frame, a box with a square hole through it. The air: a larger box
// around it. BooleanFragments makes the two volumes share the ring's faces, so that their
// meshes match there; it returns the ring first, then the air around it.
Box(1) = {-1.5, -1.5, -0.4, 3, 3, 0.8};
Box(2) = {-0.7, -0.7, -0.4, 1.4, 1.4, 0.8};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Box(4) = {-3, -3, -2, 6, 6, 4};
v() = BooleanFragments{ Volume{3}; Delete; }{ Volume{4}; Delete; };
ring = v(0);
air = v(1);
MeshSize{ PointsOf{ Volume{:}; } } = size;

// Homology requests name physical groups: the domain of the computation and, for relative
// homology, a subdomain whose chains count as zero (cycles may end on it).
Physical Volume("ring", 1) = {ring};
Physical Volume("air", 2) = {air};
Physical Surface("ring skin", 3) = Boundary{ Volume{ring}; };
outer() = Boundary{ Volume{air}; };
outer() -= Boundary{ Volume{ring}; };
Physical Surface("outer", 4) = outer();

// `Homology(dims) {{domain}, {subdomain}};` asks for bases of the homology spaces H_k of the
// domain relative to the subdomain, and saves those of the dimensions `dims` (all of them
// without the parentheses). They are computed when the mesh is made; the log gives the rank
// of every space (H_0: connected parts, H_1: loops, H_2: shells or cuts). Each basis element
// is saved as a new physical group holding the elements of one chain, numbered after the
// largest physical tag and named after the request: here "H_1{2}1", group 5, a closed line
// of edges round the ring, the path on which the field's circulation gives the current.
Homology(1) {{2}, {}};

// `Cohomology` asks for the dual bases. "H^1{2}1", group 6, is a thick cut: the edges that
// cross a surface the loop round the ring passes through once, with a value of +1 or -1 on
// each (the edge's direction says which). In an edge-element solver it is the extra basis
// function that carries the current: its circulation is +1 or -1 round any loop that goes
// once round the ring, and 0 round every loop that does not go round it.
Cohomology(1) {{2}, {}};

// Relative to the ring's skin, H_2 of the air has one basis element: "H_2{2},{3}1", group 7,
// a thin cut, a surface of triangles whose border lies on the ring and which every loop round
// the ring crosses (any such surface will do: it need not be the flat one in the hole). It is
// the cut across which a scalar potential jumps.
Homology(2) {{2}, {3}};

// Other forms: `Homology;` computes every space of the whole mesh (its volumes); `Homology
// {2};` those of group 2; `Homology {{2}, {3, 4}};` relative to two groups. A request naming a
// group that does not exist is warned of at its statement. Requests on the same domain share
// one computation.
