// Prisms over a triangulated square [0,1]^2 and hexahedra over a recombined
// one [1,2] x [0,1] (both extruded in 2 layers, recombined), under
// tetrahedra that meet the hexahedra's top quadrangles through pyramids.
Point(1) = {0, 0, 0}; Point(2) = {1, 0, 0}; Point(3) = {1, 1, 0}; Point(4) = {0, 1, 0};
Point(5) = {2, 0, 0}; Point(6) = {2, 1, 0};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {2, 5}; Line(6) = {5, 6}; Line(7) = {6, 3};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(2) = {2};
Transfinite Curve{:} = 3;
Transfinite Surface{1, 2};
Recombine Surface{2};
cells[] = Extrude {0, 0, 1} { Surface{1, 2}; Layers{2}; Recombine; };
tets[] = Extrude {0, 0, 1} { Surface{cells[6]}; };
Physical Volume("domain") = {cells[1], cells[7], tets[1]};
