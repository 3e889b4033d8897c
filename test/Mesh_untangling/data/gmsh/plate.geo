// A plate with a round hole: its left part meshed with quadrilaterals, its
// right part with triangles, extruded in 5 recombined layers: hexahedra
// and prisms, as extruded (boundary-layer) meshes are made.
lc = 0.12;
Point(1) = {0, 0, 0, lc}; Point(2) = {1.4, 0, 0, lc}; Point(3) = {2, 0, 0, lc};
Point(4) = {2, 1, 0, lc}; Point(5) = {1.4, 1, 0, lc}; Point(6) = {0, 1, 0, lc};
Point(7) = {0.7, 0.5, 0, lc};
Point(8) = {0.95, 0.5, 0, lc}; Point(9) = {0.7, 0.75, 0, lc}; Point(10) = {0.45, 0.5, 0, lc}; Point(11) = {0.7, 0.25, 0, lc};
Line(1) = {1, 2}; Line(2) = {2, 5}; Line(3) = {5, 6}; Line(4) = {6, 1};
Line(5) = {2, 3}; Line(6) = {3, 4}; Line(7) = {4, 5};
Circle(8) = {8, 7, 9}; Circle(9) = {9, 7, 10}; Circle(10) = {10, 7, 11}; Circle(11) = {11, 7, 8};
Curve Loop(1) = {1, 2, 3, 4}; Curve Loop(2) = {8, 9, 10, 11}; Curve Loop(3) = {5, 6, 7, -2};
Plane Surface(1) = {1, 2}; Plane Surface(2) = {3};
Mesh.Algorithm = 6;
Recombine Surface{1};
Extrude {0, 0, 0.6} { Surface{1, 2}; Layers{5}; Recombine; }
