// Same two boxes without physical groups: gmsh then saves every element (points, lines,
// triangles, tetrahedra) and regions must come from the volume entities.
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 0.5, 0.25};
Box(2) = {1, 0, 0, 1, 0.5, 0.25};
Coherence;
Mesh.MeshSizeMin = 0.5;
Mesh.MeshSizeMax = 0.5;
