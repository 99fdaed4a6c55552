// A 20 x 10 x 10 box with a cylindrical hole of radius 3 through it, meshed by Gmsh. It makes
// examples/box-minus-cylinder.msh, the bundled mesh that `bisect-mesh quality` grades in the
// README:  gmsh -3 box-minus-cylinder.geo -format msh41 -o box-minus-cylinder.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 20, 10, 10};
Cylinder(2) = {10, 5, -1, 0, 0, 12, 3};
BooleanDifference(3) = { Volume{1}; Delete; }{ Volume{2}; Delete; };
Mesh.MeshSizeMax = 2.5;
Mesh.MeshSizeMin = 1.0;
