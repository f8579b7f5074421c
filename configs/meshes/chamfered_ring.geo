// A rectangular ring (inner diameter 50.1 mm, 2.4 mm radial, 2.0 mm axial) with a
// 0.3 mm x 45 deg lead-in chamfer on its pressure-side rod edge, filleted (0.2 mm) where it
// meets the rod side so that no sharp corner presses on the rod: an example of a
// user-supplied seal cross-section for sealts (seal.shape = "file").
// Coordinates (r, z) in mm: x = r (radial), y = z (axial); the pressure side is at small z.
// sealts needs quadrilaterals only and four physical curves covering the boundary.
h_rod = 0.04;   // element size along the rod side (before subdivision halves it: 0.02)
h_out = 0.16;   // element size away from it

Point(1) = {25.05, 1.0, 0, h_rod};
Point(2) = {25.05, -0.6172, 0, h_rod};     // the rod side ends where the edge fillet starts
Point(3) = {25.10858, -0.75858, 0, h_rod}; // the fillet meets the chamfer
Point(4) = {25.35, -1.0, 0, h_rod};
Point(5) = {27.45, -1.0, 0, h_out};
Point(6) = {27.45, 1.0, 0, h_out};
Point(7) = {25.25, -0.6172, 0, h_rod};     // fillet centre: radius 0.2 mm, tangent to both

Line(1) = {1, 2};          // rod side
Circle(2) = {2, 7, 3};     // 0.2 mm fillet between rod side and chamfer (part of the rod side)
Line(3) = {3, 4};          // chamfer (faces the pressurised fluid)
Line(4) = {4, 5};          // pressure side
Line(5) = {5, 6};          // groove bottom
Line(6) = {6, 1};          // atmosphere side
Curve Loop(1) = {1, 2, 3, 4, 5, 6};
Plane Surface(1) = {1};

Physical Curve("rod_side") = {1, 2};
Physical Curve("pressure_side") = {3, 4};
Physical Curve("groove") = {5};
Physical Curve("atmosphere_side") = {6};
Physical Surface("seal") = {1};

Mesh.Algorithm = 8;             // frontal-Delaunay for quads
Mesh.RecombineAll = 1;
Mesh.SubdivisionAlgorithm = 1;  // split every element into quads: no triangle is left
