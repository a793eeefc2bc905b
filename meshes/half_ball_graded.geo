// Hertz half ball (issue 26), graded towards the pole: the mesh of postproc/getfem_hertz3d.py (the generator half_ball meshes meshes/half_ball.geo, uniform; to be one file).
// { x^2 + y^2 + (z - R)^2 <= R^2, z <= R }: flat face on top at z = R (its centre (0, 0, R), the
// ball's centre, is a mesh node), touching the plane z = 0 at the origin (a mesh node: the pole).
//   gmsh half_ball.geo -3 -format msh22 -setnumber R 8 -setnumber h 0.025 -setnumber grading 0.1 -o half_ball.msh
// (28887 dofs in P1, the fine mesh of datafiles/scene3d/GETFEM.md; the defaults: its coarse mesh)
// msh 4.1 (-format msh41) gives the same mesh, but GetFEM 5.4's importer renumbers its regions
// ("Two regions share the same number": 1, 2, 6 instead of 1, 2, 3): give GetFEM msh 2.2.
// Physical groups: volume 1; the flat top face 2 (where the load is applied); the curved face 3
// (the contact candidates).
// Mesh size: h + grading * d at distance d from the origin (the first contact point), capped at
// `cap` (default R / 4); grading = 0 gives a uniform mesh of size h.
DefineConstant[ R = 8, h = 0.08, grading = 0.2, cap = 0 ]; // the coarse mesh of getfem_hertz3d.py

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

hmax = (cap > 0) ? cap : R / 4;
hmax = (hmax > h) ? hmax : h;

// OpenCASCADE's sphere between the polar angles -Pi/2 (the pole at the origin) and 0 (the equator).
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
