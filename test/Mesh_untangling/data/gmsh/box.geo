// A unit box of tetrahedra; its bottom face (z = 0) is the physical group "fixed".
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Mesh.MeshSizeMin = 0.6;
Mesh.MeshSizeMax = 0.6;
Physical Surface("fixed") = {5};
Physical Volume("domain") = {1};
