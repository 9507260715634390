// Axisymmetric fixed orifice (model.md 4.2, D11): upstream plenum, cylindrical bore with sharp
// edges, downstream chamber. x along the axis (flow in +x), y = r; coordinates in mm. servodrift sets
// every parameter through the gmsh SDK (ONELAB "Parameters/<name>") with the dimensions at the case's
// temperature; the defaults are RV-1 at 40 degC, so that `gmsh fixed_orifice.geo' shows it.
//
// Five structured blocks (all quadrilaterals): plenum core (r < r0) and ring, bore, chamber core and
// ring. Cells are graded towards the bore's edges and wall; `res' scales every count, and the bore
// has 30 res cells across its radius.
// Physical curves: inlet (the plenum's back face), outlet (the chamber's cylindrical side, the
// passage on to the nozzles; entrainment comes back in through it from rest), wall (orifice plate
// faces, bore wall, plenum side wall, the chamber's far face, on which the jet stagnates), axis.
DefineConstant[
  r0 = {0.1125, Name "Parameters/r0"},  // bore radius D_0/2
  l = {0.50, Name "Parameters/l"},      // bore length l_0
  ru = {0.675, Name "Parameters/ru"},   // plenum radius
  lu = {0.675, Name "Parameters/lu"},   // plenum length
  rd = {0.90, Name "Parameters/rd"},    // chamber radius
  ld = {2.25, Name "Parameters/ld"},    // chamber length
  res = {1, Name "Parameters/res"}      // resolution: multiplies every cell count
];
nr = Ceil(30 * res);                     // across the bore radius
nb = Ceil(2.4 * nr * (l / r0) / 4.44);
nu = Ceil(0.9 * nr);                     // along the plenum
nru = Ceil(0.6 * nr);                    // across the plenum ring
nd = Ceil(2.2 * nr);                     // along the chamber
nrd = Ceil(0.8 * nr);                    // across the chamber ring

Point(1) = {-lu, 0, 0}; Point(2) = {0, 0, 0}; Point(3) = {l, 0, 0}; Point(4) = {l + ld, 0, 0};
Point(5) = {-lu, r0, 0}; Point(6) = {0, r0, 0}; Point(7) = {l, r0, 0}; Point(8) = {l + ld, r0, 0};
Point(9) = {-lu, ru, 0}; Point(10) = {0, ru, 0};
Point(11) = {l, rd, 0}; Point(12) = {l + ld, rd, 0};

Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};      // axis
Line(4) = {5, 6}; Line(5) = {6, 7}; Line(6) = {7, 8};      // r = r0 (5: bore wall)
Line(7) = {1, 5}; Line(8) = {2, 6}; Line(9) = {3, 7}; Line(10) = {4, 8};
Line(11) = {5, 9}; Line(12) = {6, 10}; Line(13) = {9, 10}; // plenum ring
Line(14) = {7, 11}; Line(15) = {8, 12}; Line(16) = {11, 12}; // chamber ring

Curve Loop(1) = {1, 8, -4, -7};   Plane Surface(1) = {1}; // plenum core
Curve Loop(2) = {4, 12, -13, -11}; Plane Surface(2) = {2}; // plenum ring
Curve Loop(3) = {2, 9, -5, -8};   Plane Surface(3) = {3}; // bore
Curve Loop(4) = {3, 10, -6, -9};  Plane Surface(4) = {4}; // chamber core
Curve Loop(5) = {6, 15, -16, -14}; Plane Surface(5) = {5}; // chamber ring

// along x: small cells at the bore's ends
Transfinite Curve{1, 4, 13} = nu + 1 Using Progression 0.94;
Transfinite Curve{2, 5} = nb + 1 Using Bump 0.2;
Transfinite Curve{3, 6, 16} = nd + 1 Using Progression 1.04;
// along r: small cells at the bore wall's radius r0
Transfinite Curve{7, 8, 9, 10} = nr + 1 Using Progression 0.95;
Transfinite Curve{11, 12} = nru + 1 Using Progression 1.1;
Transfinite Curve{14, 15} = nrd + 1 Using Progression 1.08;
Transfinite Surface{1, 2, 3, 4, 5};
Recombine Surface{1, 2, 3, 4, 5};

Physical Surface("fluid") = {1, 2, 3, 4, 5};
Physical Curve("inlet") = {7, 11};
Physical Curve("outlet") = {16};
Physical Curve("wall") = {12, 5, 14, 13, 10, 15};
Physical Curve("axis") = {1, 2, 3};
