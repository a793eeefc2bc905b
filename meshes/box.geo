// Box [0, lx] x [0, ly] x [0, lz] of P1 tetrahedra (issue 26, the first 3D body).
//   gmsh box.geo -3 -format msh41 -setnumber lx 1 -setnumber ly 1 -setnumber lz 1 -setnumber h 0.5
// Physical Volume 1; Physical Surface 1 the base z = 0 (where it is clamped), 2 the top z = lz,
// 3 the four sides. Mesh size h everywhere.
DefineConstant[ lx = 1, ly = 1, lz = 1, h = 0.5 ];

SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;

Box(1) = {0, 0, 0, lx, ly, lz};
// OpenCASCADE numbers a box's faces x = 0, x = lx, y = 0, y = ly, z = 0, z = lz.
Physical Volume(1) = {1};
Physical Surface(1) = {5};
Physical Surface(2) = {6};
Physical Surface(3) = {1, 2, 3, 4};
