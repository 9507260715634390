// Validation geometry: a round jet from a pipe impinging normally on a flat plate (Cooper, Jackson,
// Launder and Liao 1993), axisymmetric, x along the axis towards the plate, y = r, in pipe diameters
// D = 1: the pipe's last `lp' diameters (inner radius 0.5, the lip's outer radius `rl'), the jet's
// exit plane at x = 0, the plate at x = `h', the radial outlet at r = `ro'. Four structured blocks
// of quadrilaterals: the pipe, the jet's core (r < 0.5), the ring in the lip's shadow and the outer
// region. Cells shrink towards the plate (first cell about `wall' D) and the pipe's wall.
// Boundaries: inlet (the pipe's upstream end), pipe (its wall), lip (its end face), entrainment (the
// exit plane outside the lip: ambient fluid at rest enters there), plate, outlet (r = ro), axis.
DefineConstant[ lp = {1, Name "Parameters/lp"}, h = {2, Name "Parameters/h"}, rl = {0.53125, Name "Parameters/rl"},
  ro = {5, Name "Parameters/ro"}, nx = {80, Name "Parameters/nx"}, nxp = {20, Name "Parameters/nxp"},
  nr = {30, Name "Parameters/nr"}, nrl = {4, Name "Parameters/nrl"}, nro = {60, Name "Parameters/nro"},
  gx = {0.93, Name "Parameters/gx"}, gr = {0.86, Name "Parameters/gr"}, gro = {1.06, Name "Parameters/gro"} ];
Point(1) = {-lp, 0, 0}; Point(2) = {0, 0, 0}; Point(3) = {h, 0, 0};
Point(4) = {-lp, 0.5, 0}; Point(5) = {0, 0.5, 0}; Point(6) = {h, 0.5, 0};
Point(7) = {0, rl, 0}; Point(8) = {h, rl, 0};
Point(9) = {0, ro, 0}; Point(10) = {h, ro, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};     // axis
Line(3) = {4, 5}; Line(4) = {5, 6};     // r = 0.5: the pipe's wall, then inside the free region
Line(5) = {7, 8}; Line(6) = {9, 10};    // r = rl; the outlet
Line(7) = {1, 4}; Line(8) = {2, 5}; Line(9) = {3, 6}; // the inlet, the exit plane, the plate under the pipe
Line(10) = {5, 7}; Line(11) = {6, 8};   // the lip; the plate under it
Line(12) = {7, 9}; Line(13) = {8, 10};  // the entrainment plane; the plate beyond
Curve Loop(1) = {1, 8, -3, -7}; Plane Surface(1) = {1};
Curve Loop(2) = {2, 9, -4, -8}; Plane Surface(2) = {2};
Curve Loop(3) = {4, 11, -5, -10}; Plane Surface(3) = {3};
Curve Loop(4) = {5, 13, -6, -12}; Plane Surface(4) = {4};
Transfinite Curve{2, 4, 5, 6} = nx + 1 Using Progression gx;   // shrinking towards the plate
Transfinite Curve{1, 3} = nxp + 1 Using Progression 0.95;      // shrinking towards the exit
Transfinite Curve{7, 8, 9} = nr + 1 Using Progression gr;      // shrinking towards the pipe's wall
Transfinite Curve{10, 11} = nrl + 1;
Transfinite Curve{12, 13} = nro + 1 Using Progression gro;     // growing outwards
Transfinite Surface{1, 2, 3, 4};
Recombine Surface{1, 2, 3, 4};
Physical Surface("fluid") = {1, 2, 3, 4};
Physical Curve("inlet") = {7};
Physical Curve("pipe") = {3};
Physical Curve("lip") = {10};
Physical Curve("entrainment") = {12};
Physical Curve("plate") = {9, 11, 13};
Physical Curve("outlet") = {6};
Physical Curve("axis") = {1, 2};
