// A unit box of 2 x 2 x 2 hexahedra (transfinite, recombined); no group "fixed".
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Transfinite Curve{:} = 3;
Transfinite Surface{:};
Recombine Surface{:};
Transfinite Volume{1};
Physical Volume("domain") = {1};
