// Disc of centre (cx, cy) and radius R in four quarter arcs (SCENES.md, scenes 4 and 8a).
//   gmsh disc.geo -2 -format msh41 -setnumber cx 10 -setnumber cy 10 -setnumber R 10
//                 -setnumber N 512 -setnumber grading 0
// The bottom quarter carries N/4 uniform segments; so does each other quarter (graded_arcs = 0),
// or the size law below sets its segments (graded_arcs = 1: the mesh fine only near the
// bottom). Physical curves: 1 left quarter (x1 <= cx - R/sqrt2), 2 top, 3 bottom (the contact
// side), 4 right.
// Mesh size: h = 2 pi R / N on the bottom quarter, h + grading * d at distance d from it, capped
// at R/4 (grading = 0 gives a uniform mesh).
DefineConstant[ cx = 0, cy = 0, R = 1, N = 16, grading = 0, graded_arcs = 0 ];

General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.Algorithm = 6;     // frontal-Delaunay
Mesh.MeshSizeFromPoints = 0;
Mesh.MeshSizeFromCurvature = 0;
Mesh.MeshSizeExtendFromBoundary = 0;

h = 2 * Pi * R / N;
cap = (R / 4 > h) ? R / 4 : h;
s = R * Sqrt(2) / 2;

Point(1) = {cx, cy, 0};
Point(2) = {cx + s, cy + s, 0};
Point(3) = {cx - s, cy + s, 0};
Point(4) = {cx - s, cy - s, 0};
Point(5) = {cx + s, cy - s, 0};
Circle(1) = {5, 1, 2}; // right
Circle(2) = {2, 1, 3}; // top
Circle(3) = {3, 1, 4}; // left
Circle(4) = {4, 1, 5}; // bottom
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (graded_arcs == 0)
  Transfinite Curve {1, 2, 3, 4} = N / 4 + 1;
Else
  Transfinite Curve {4} = N / 4 + 1;
EndIf

Field[1] = Distance;
Field[1].CurvesList = {4};
Field[1].NumPointsPerCurve = 4 * N;
Field[2] = MathEval;
Field[2].F = Sprintf("%.17g + %.17g * F1", h, grading);
Field[3] = MathEval;
Field[3].F = Sprintf("%.17g", cap);
Field[4] = Min;
Field[4].FieldsList = {2, 3};
Background Field = 4;

Physical Curve(1) = {3};
Physical Curve(2) = {2};
Physical Curve(3) = {4};
Physical Curve(4) = {1};
Physical Surface(1) = {1};
