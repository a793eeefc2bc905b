// Hertz half ball (issue 26, the 3D scene 7a): { |x - (0, 0, R)| <= R, x3 <= R }, the lower
// half of the ball of centre (0, 0, R), its lowest point (the pole) at the origin, a mesh node.
//   gmsh half_ball.geo -3 -format msh41 -setnumber R 1 -setnumber h 0.25
//   gmsh half_ball.geo -3 -format msh22 -setnumber R 8 -setnumber h 0.025 -setnumber grading 0.1
// Physical Volume 1; Physical Surface 3 the half sphere (Gamma3, the contact side), 2 the flat
// top x3 = R; Physical Point 1 the top centre (0, 0, R), a mesh node.
// Mesh size: h + grading * d at distance d from the pole (where the contact starts), capped at
// `cap` (cap = 0: R / 4; never below h). grading = 0 (the default): uniform, size h everywhere.
// GetFEM 5.4 reads the physical groups of msh 2.2 (-format msh22) as regions 1, 2, 3; from msh 4.1
// it renumbers them ("Two regions share the same number").
DefineConstant[ R = 1, h = 0.25, grading = 0, cap = 0 ];

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

hmax = (cap > 0) ? cap : R / 4;
hmax = (hmax > h) ? hmax : h;

// OpenCASCADE's sphere between the polar angles -Pi/2 (the pole) and 0 (the equator).
Sphere(1) = {0, 0, R, R, -Pi / 2, 0, 2 * Pi};
Point(100) = {0, 0, R};
top() = Surface In BoundingBox{-2 * R, -2 * R, R - 1e-6 * R, 2 * R, 2 * R, R + 1e-6 * R};
curved() = Surface{:};
curved() -= top();
Point{100} In Surface{top(0)};

Field[1] = MathEval;
Field[1].F = Sprintf("%.17g + %.17g * sqrt(x * x + y * y + z * z)", h, grading);
Field[2] = MathEval;
Field[2].F = Sprintf("%.17g", hmax);
Field[3] = Min;
Field[3].FieldsList = {1, 2};
Background Field = 3;

Physical Volume(1) = {1};
Physical Surface(2) = {top()};
Physical Surface(3) = {curved()};
Physical Point(1) = {100};
