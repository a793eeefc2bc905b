// The ball of scene 8a (thesis ch. 8.5, Fig 8.1): a disc of centre (cx, cy) and radius R whose
// whole circle is Gamma3 (physical curve 3, N uniform segments: N contact nodes), sub-domain 1.
//   gmsh ball.geo -2 -format msh41 -setnumber cy 25 -setnumber N 128 -setnumber h 0.2
//                 -setnumber grading 0 -o ball.msh
// Mesh size inside: h + grading * d at distance d from the lowest point (cx, cy - R), where the
// ball hits the foundation, capped at `cap` (default 2 pi R / N, the spacing on the circle);
// h = 0 means the spacing on the circle. The circle keeps its N uniform segments whatever h is,
// so the contact nodes (the thesis's 128 multiplier nodes) do not change with the bulk mesh.
DefineConstant[ cx = 0, cy = 0, R = 1, N = 16, h = 0, grading = 0, cap = 0 ];

General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.Algorithm = 5;     // Delaunay (frontal-Delaunay (6) fails on some sizes finer than the circle)
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

spacing = 2 * Pi * R / N;
h0 = (h > 0) ? h : spacing;
hmax = (cap > 0) ? cap : spacing;
hmax = (hmax > h0) ? hmax : h0;

Point(1) = {cx, cy, 0};
Point(2) = {cx, cy - R, 0}; // the lowest point: first contact
Point(3) = {cx + R, cy, 0};
Point(4) = {cx, cy + R, 0};
Point(5) = {cx - R, cy, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2, 3, 4} = N / 4 + 1;

Field[1] = Distance;
Field[1].NodesList = {2};
Field[2] = MathEval;
Field[2].F = Sprintf("%.17g + %.17g * F1", h0, grading);
Field[3] = MathEval;
Field[3].F = Sprintf("%.17g", hmax);
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;

Physical Curve(3) = {1, 2, 3, 4};
Physical Surface(1) = {1};
