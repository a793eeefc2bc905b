// Hertz half ball (issue 26, the 3D scene 7a): { |x - (0, 0, R)| <= R, x3 <= R }, the lower
// half of the ball of centre (0, 0, R), its lowest point at the origin.
//   gmsh half_ball.geo -3 -format msh41 -setnumber R 1 -setnumber h 0.25
// Physical Volume 1; Physical Surface 3 the half sphere (Gamma3, the contact side), 2 the flat
// top x3 = R; Physical Point 1 the top centre (0, 0, R), a mesh node. Mesh size h everywhere.
DefineConstant[ R = 1, h = 0.25 ];

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;

Sphere(1) = {0, 0, R, R};
Box(2) = {-2 * R, -2 * R, R, 4 * R, 4 * R, 2 * R};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
eps = 1e-6 * R;
top() = Surface In BoundingBox{-2 * R, -2 * R, R - eps, 2 * R, 2 * R, R + eps};
all() = Surface{:};
Point(100) = {0, 0, R};
Point{100} In Surface{top(0)};
Physical Volume(1) = {3};
Physical Surface(3) = {all()};
Physical Surface(3) -= {top()};
Physical Surface(2) = {top()};
Physical Point(1) = {100};
