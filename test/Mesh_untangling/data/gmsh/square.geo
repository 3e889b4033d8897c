// A unit square of triangles; its left side (x = 0) is the physical group "fixed".
SetFactory("OpenCASCADE");
Rectangle(1) = {0, 0, 0, 1, 1};
Mesh.MeshSizeMin = 0.4;
Mesh.MeshSizeMax = 0.4;
Physical Curve("fixed") = {4};
Physical Surface("domain") = {1};
