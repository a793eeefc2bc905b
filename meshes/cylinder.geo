// A wheel-like cylinder of P1 tetrahedra (issue 26): radius R, axis along x2 from x2 = 0 to
// x2 = L through (0, *, R), so that it rests on the plane x3 = 0 along the x2 axis.
//   gmsh cylinder.geo -3 -format msh41 -setnumber R 1 -setnumber L 0.5 -setnumber h 0.2
// Physical Volume 1; Physical Surface 3 the curved side (Gamma3, the tread), 2 the two flat
// ends. Mesh size h everywhere.
DefineConstant[ R = 1, L = 0.5, h = 0.2 ];

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;

Cylinder(1) = {0, 0, R, 0, L, 0, R};
eps = 1e-6 * (R + L);
ends() = Surface In BoundingBox{-2 * R, -eps, -eps, 2 * R, eps, 2 * R + eps};
ends() += Surface In BoundingBox{-2 * R, L - eps, -eps, 2 * R, L + eps, 2 * R + eps};
Physical Volume(1) = {1};
Physical Surface(3) = {Surface{:}};
Physical Surface(3) -= {ends()};
Physical Surface(2) = {ends()};
