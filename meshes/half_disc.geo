// Hertz half disc (SCENES.md, scene 7a): { x1^2 + (x2 - R)^2 <= R^2, x2 <= R }.
//   gmsh half_disc.geo -2 -format msh41 -setnumber R 8 -setnumber N 256 -setnumber grading 0
// The lower half circle carries exactly N uniform segments (Gamma3, physical curve 3) so that
// N + 1 contact nodes sit on it; the top diameter is physical curve 2; the top centre (0, R),
// where the horizontal displacement is fixed, is a mesh node and physical point 1.
// Mesh size: h = pi R / N on the arc, h + grading * d at distance d from the arc, capped at R/4
// (grading = 0 gives the uniform mesh of the thesis).
DefineConstant[ R = 8, N = 16, grading = 0 ];

General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.Algorithm = 6;     // frontal-Delaunay
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

h = Pi * R / N;
cap = (R / 4 > h) ? R / 4 : h;

Point(1) = {0, R, 0}; // circle centre = top centre node
Point(2) = {-R, R, 0};
Point(3) = {0, 0, 0}; // lowest point: the first contact node
Point(4) = {R, R, 0};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Line(3) = {4, 1};
Line(4) = {1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 2} = N / 2 + 1;

// Distance to the arc is R - |x - centre| inside the disc.
Field[1] = MathEval;
Field[1].F = Sprintf("%.17g + %.17g * (%.17g - sqrt(x * x + (y - %.17g) * (y - %.17g)))",
                     h, grading, R, R, R);
Field[2] = MathEval;
Field[2].F = Sprintf("%.17g", cap);
Field[3] = Min;
Field[3].FieldsList = {1, 2};
Background Field = 3;

Physical Curve(3) = {1, 2};
Physical Curve(2) = {3, 4};
Physical Point(1) = {1};
Physical Surface(1) = {1};
