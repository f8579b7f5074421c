// A rectangular ring (inner diameter 50.1 mm, 2.4 mm radial, 2.0 mm axial) with a
// 0.3 mm x 45 deg lead-in chamfer on its pressure-side rod edge: an example of a
// user-supplied seal cross-section for sealts (seal.shape = "file").
// Coordinates (r, z) in mm: x = r (radial), y = z (axial); the pressure side is at small z.
// sealts needs quadrilaterals only and four physical curves covering the boundary.
h_rod = 0.04;   // element size along the rod side (before subdivision halves it: 0.02)
h_out = 0.16;   // element size away from it

Point(1) = {25.05, 1.0, 0, h_rod};
Point(2) = {25.05, -0.7, 0, h_rod};
Point(3) = {25.35, -1.0, 0, h_rod};
Point(4) = {27.45, -1.0, 0, h_out};
Point(5) = {27.45, 1.0, 0, h_out};

Line(1) = {1, 2};   // rod side
Line(2) = {2, 3};   // chamfer (faces the pressurised fluid)
Line(3) = {3, 4};   // pressure side
Line(4) = {4, 5};   // groove bottom
Line(5) = {5, 1};   // atmosphere side
Curve Loop(1) = {1, 2, 3, 4, 5};
Plane Surface(1) = {1};

Physical Curve("rod_side") = {1};
Physical Curve("pressure_side") = {2, 3};
Physical Curve("groove") = {4};
Physical Curve("atmosphere_side") = {5};
Physical Surface("seal") = {1};

Mesh.Algorithm = 8;             // frontal-Delaunay for quads
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;  // split every element into quads: no triangle is left
