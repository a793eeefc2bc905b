// The pad of creep_slip.dat: the box [0, 1] x [0, 1] x [0, 0.5] of P1 tetrahedra, each face its
// own reference (the side tractions differ per face).
//   gmsh creep_slip.geo -3 -format msh41 -o creep_slip.msh
// Physical Surface 1 the base x3 = 0, 2 the top x3 = 0.5, 3 and 4 the faces x1 = 0 and 1, 5 and
// 6 the faces x2 = 0 and 1. Mesh size 0.25.
SetFactory("OpenCASCADE");
General.NumThreads = 1; // one thread: the same input gives the same mesh
Mesh.CharacteristicLengthMin = 0.25;
Mesh.CharacteristicLengthMax = 0.25;
Box(1) = {0, 0, 0, 1, 1, 0.5};
// OpenCASCADE numbers a box's faces x = 0, x = lx, y = 0, y = ly, z = 0, z = lz.
Physical Volume(1) = {1};
Physical Surface(1) = {5};
Physical Surface(2) = {6};
Physical Surface(3) = {1};
Physical Surface(4) = {2};
Physical Surface(5) = {3};
Physical Surface(6) = {4};
