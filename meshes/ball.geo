// Ball of centre (cx, cy, cz) and radius R of P1 tetrahedra (issue 26, the 3D disc).
//   gmsh ball.geo -3 -format msh41 -setnumber R 1 -setnumber h 0.25
// Physical Volume 1; Physical Surface 3 the sphere (Gamma3, the contact side; one surface:
// the obstacle decides where the contact is). Mesh size h everywhere.
DefineConstant[ cx = 0, cy = 0, cz = 0, R = 1, h = 0.25 ];

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;

Sphere(1) = {cx, cy, cz, R};
Physical Volume(1) = {1};
Physical Surface(3) = {Surface{:}};
