// geomesh tutorial 17: anisotropic triangles, stretched along a flow.
//
// Near a wall a flow changes fast across the wall and slowly along it: the best triangles
// there are long and thin, short across and long along. An anisotropic size is a metric: a
// symmetric matrix M at each point, asking for length 1/sqrt(e' M e) along each unit
// direction e (for M = diag(1/hx^2, 1/hy^2): hx along x, hy along y). Mesh.Algorithm = 7
// meshes to such a metric, given by a MathEvalAniso background field (as here) or by a
// view of tensors (TT records) as background mesh. Mesh.AnisoMax bounds the stretching
// (the ratio of the largest to the smallest size at a point) and Mesh.SmoothRatio how fast
// sizes may grow from one element to the next.
//
// Run:  geomesh t17.geo -2          (writes t17.msh)

// A channel of 4 x 1 with walls at y = 0 and y = 1.
Point(1) = {0, 0, 0};
Point(2) = {4, 0, 0};
Point(3) = {4, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("channel", 1) = {1};

// Along the channel, size 0.2 everywhere; across it, 0.01 at the walls growing to 0.1 at
// the centre line (d is the distance to the nearer wall).
Field[1] = MathEvalAniso;
Field[1].M11 = "1 / 0.2^2";
Field[1].M22 = "1 / (0.01 + 0.18 * Min(y, 1 - y))^2";
Field[1].M33 = "1";
Field[1].M12 = "0";
Field[1].M13 = "0";
Field[1].M23 = "0";
Background Field = 1;

Mesh.Algorithm = 7;
Mesh.AnisoMax = 100;
Mesh.SmoothRatio = 2;
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeExtendFromBoundary = 0;
