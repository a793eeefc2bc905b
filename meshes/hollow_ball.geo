// Hollow ball crushed on a plane (issue 28, the hyperelastic crush): the shell
// R_in <= |x - (0, 0, R)| <= R cut flat at x3 = top (R < top < 2 R, the cut above the cavity
// when top >= R + R_in, so the top is a solid disc the press holds and the cavity is closed),
// its lowest point (the pole) at the origin, a mesh node.
//   gmsh hollow_ball.geo -3 -format msh22 -setnumber R 1 -setnumber R_in 0.6 -setnumber top 1.8
//        -setnumber h 0.05 -setnumber grading 0.3
// Physical Volume 1; Physical Surface 2 the flat top (held by the press), 3 the outer sphere
// (Gamma3, the contact side), 4 the cavity's sphere (free).
// Mesh size: h + grading * d at distance d from the pole, capped at `cap` (cap = 0: R / 4;
// never below h). msh 2.2 for GetFEM 5.4 (it renumbers the physical groups of msh 4.1).
DefineConstant[ R = 1, R_in = 0.6, top = 1.8, h = 0.25, grading = 0, cap = 0 ];

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

If (!(R_in > 0 && R_in < R && top > R && top < 2 * R))
  Error("hollow_ball.geo needs 0 < R_in < R < top < 2 R");
  Abort;
EndIf

hmax = (cap > 0) ? cap : R / 4;
hmax = (hmax > h) ? hmax : h;

// OpenCASCADE's sphere between the polar angles -Pi/2 (the pole) and the cut's.
Sphere(1) = {0, 0, R, R, -Pi / 2, Asin((top - R) / R), 2 * Pi};
Sphere(2) = {0, 0, R, R_in};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
eps = 1e-6 * R;
flat() = Surface In BoundingBox{-2 * R, -2 * R, top - eps, 2 * R, 2 * R, top + eps};
cavity() = Surface In BoundingBox{-R_in - eps, -R_in - eps, R - R_in - eps,
                                  R_in + eps, R_in + eps, R + R_in + eps};
outer() = Surface{:};
outer() -= flat();
outer() -= cavity();

Field[1] = MathEval;
Field[1].F = Sprintf("%.17g + %.17g * sqrt(x * x + y * y + z * z)", h, grading);
Field[2] = MathEval;
Field[2].F = Sprintf("%.17g", hmax);
Field[3] = Min;
Field[3].FieldsList = {1, 2};
Background Field = 3;

Physical Volume(1) = {3};
Physical Surface(2) = {flat()};
Physical Surface(3) = {outer()};
Physical Surface(4) = {cavity()};
