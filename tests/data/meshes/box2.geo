// Two boxes side by side sharing a face: two volumes, physical groups on both volumes and on
// all surfaces but xmax (surface 7; its triangles are not saved), coarse enough that the files
// stay a few KB. The box2_* files of this folder were written once with gmsh 4.8.4:
//   gmsh -3 [-order 2] box2.geo -format msh41|msh22|inp -o box2_o1|o2[_v22].msh|.inp
//   gmsh -3 box2_nophys.geo -format msh41 -o box2_nophys_o1.msh
//   gmsh -3 -order 2 box2_nophys.geo -format msh22 -o box2_nophys_o2_v22.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.5, 0.25};
Box(2) = {1, 0, 0, 1, 0.5, 0.25};
Coherence;
Mesh.MeshSizeMin = 0.5;
Mesh.MeshSizeMax = 0.5;
Physical Volume("left") = {1};
Physical Volume("right") = {2};
Physical Surface("xmin") = {1};
Physical Surface("rest") = {2,3,4,5,6,8,9,10,11};
