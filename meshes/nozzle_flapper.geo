// Axisymmetric nozzle-flapper gap (model.md 4.2, D11): part of the control cavity (the nozzle
// chamber), the nozzle bore, the flat land of the nozzle tip, the gap h to a flat flapper normal to
// the axis, and the return chamber to a radius several land radii out. x along the axis towards the
// flapper (the nozzle's exit plane at x = 0, the flapper at x = h), y = r; coordinates in mm.
// servodrift sets every parameter through the gmsh SDK (ONELAB "Parameters/<name>") with the
// dimensions at the case's temperature; the defaults are RV-1 at 40 degC.
//
// Seven structured blocks (all quadrilaterals): chamber core and ring, bore, the gap under the bore,
// the gap over the land, the gap beyond the land and the return chamber behind the nozzle tip. The
// gap has 20 res cells across; `res' scales every count.
// Physical curves: inlet (the chamber's back face), outlet (the return chamber's outer and back
// faces), nozzle (chamber walls, bore), land (the tip's flat face), nozzle_outside (the tip's
// cylinder), flapper (the flat face at x = h), axis.
DefineConstant[
  rn = {0.20, Name "Parameters/rn"},    // bore radius D_N/2
  rl = {0.35, Name "Parameters/rl"},    // land radius D_land/2
  h = {0.040, Name "Parameters/h"},     // gap
  ro = {1.40, Name "Parameters/ro"},    // outlet radius
  rc = {0.40, Name "Parameters/rc"},    // chamber radius
  lc = {0.40, Name "Parameters/lc"},    // chamber length
  lb = {0.80, Name "Parameters/lb"},    // bore length
  le = {0.50, Name "Parameters/le"},    // return chamber depth behind the nozzle's exit plane
  res = {1, Name "Parameters/res"}      // resolution: multiplies every cell count
];
nh = Ceil(20 * res);                 // across the gap
nrn = Ceil(30 * res);                // across the bore radius
nland = Ceil(40 * res);              // along the land
nout = Ceil(40 * res);               // beyond the land
nb = Ceil(40 * res);                 // along the bore
nc = Ceil(12 * res);                 // along the chamber
nrc = Ceil(10 * res);                // across the chamber ring
ne = Ceil(16 * res);                 // along the return chamber's depth

x0 = -lb - lc;
Point(1) = {x0, 0, 0}; Point(2) = {-lb, 0, 0}; Point(3) = {0, 0, 0}; Point(4) = {h, 0, 0};
Point(5) = {x0, rn, 0}; Point(6) = {-lb, rn, 0}; Point(7) = {0, rn, 0}; Point(8) = {h, rn, 0};
Point(9) = {x0, rc, 0}; Point(10) = {-lb, rc, 0};
Point(11) = {0, rl, 0}; Point(12) = {h, rl, 0}; Point(13) = {-le, rl, 0};
Point(14) = {-le, ro, 0}; Point(15) = {0, ro, 0}; Point(16) = {h, ro, 0};

Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4};         // axis
Line(4) = {5, 6}; Line(5) = {6, 7}; Line(6) = {7, 8};         // r = rn (5: bore wall)
Line(7) = {1, 5}; Line(8) = {2, 6}; Line(9) = {3, 7}; Line(10) = {4, 8}; // across the bore radius
Line(11) = {5, 9}; Line(12) = {6, 10}; Line(13) = {9, 10};    // chamber ring
Line(14) = {7, 11}; Line(15) = {8, 12};                        // along the land
Line(16) = {11, 12};                                           // across the gap at the land's edge
Line(17) = {11, 15}; Line(18) = {12, 16}; Line(19) = {15, 16}; // beyond the land
Line(20) = {13, 11}; Line(21) = {13, 14}; Line(22) = {14, 15}; // return chamber

Curve Loop(1) = {1, 8, -4, -7};     Plane Surface(1) = {1}; // chamber core
Curve Loop(2) = {4, 12, -13, -11};  Plane Surface(2) = {2}; // chamber ring
Curve Loop(3) = {2, 9, -5, -8};     Plane Surface(3) = {3}; // bore
Curve Loop(4) = {3, 10, -6, -9};    Plane Surface(4) = {4}; // gap under the bore
Curve Loop(5) = {6, 15, -16, -14};  Plane Surface(5) = {5}; // gap over the land
Curve Loop(6) = {16, 18, -19, -17}; Plane Surface(6) = {6}; // gap beyond the land
Curve Loop(7) = {20, 17, -22, -21}; Plane Surface(7) = {7}; // return chamber behind the tip

// across the gap: small cells at the land and the flapper
Transfinite Curve{3, 6, 16, 19} = nh + 1 Using Bump 0.5;
// along r under the bore: small cells towards the bore wall and the land's inner edge
Transfinite Curve{7, 8, 9, 10} = nrn + 1 Using Progression 0.95;
Transfinite Curve{11, 12} = nrc + 1 Using Progression 1.1;
Transfinite Curve{14, 15} = nland + 1 Using Bump 0.3;
Transfinite Curve{17, 18, 21} = nout + 1 Using Progression 1.06;
// along x
Transfinite Curve{1, 4, 13} = nc + 1 Using Progression 0.9;
Transfinite Curve{2, 5} = nb + 1 Using Progression 0.95;
Transfinite Curve{20, 22} = ne + 1 Using Progression 0.85;
Transfinite Surface{1, 2, 3, 4, 5, 6, 7};
Recombine Surface{1, 2, 3, 4, 5, 6, 7};

Physical Surface("fluid") = {1, 2, 3, 4, 5, 6, 7};
Physical Curve("inlet") = {7, 11};
Physical Curve("outlet") = {19, 22, 21};
Physical Curve("nozzle") = {13, 12, 5};
Physical Curve("land") = {14};
Physical Curve("nozzle_outside") = {20};
Physical Curve("flapper") = {10, 15, 18};
Physical Curve("axis") = {1, 2, 3};
