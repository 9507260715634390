// Validation geometry: the backward-facing step of Driver and Seegmiller (1985), planar, in step
// heights H = 1: the upstream channel x in [-lu, 0], y in [1, 9] (8 H), the step face at x = 0, the
// downstream channel x in [0, ld], y in [0, 9] (expansion ratio 9/8). Three structured blocks of
// quadrilaterals: the upstream channel, the downstream part below the step's top (y < 1) and above
// it. Cells are small at the walls (first cell about `wall' H) and at the step's top, where the
// shear layer leaves the corner, and grow downstream.
// Boundaries: inlet (x = -lu), outlet (x = ld), bottom (y = 0, x > 0), step (x = 0, y < 1),
// upstream_bottom (y = 1, x < 0), top (y = 9).
DefineConstant[ lu = {4, Name "Parameters/lu"}, ld = {30, Name "Parameters/ld"},
  nxu = {30, Name "Parameters/nxu"}, nxd = {140, Name "Parameters/nxd"},
  nyl = {40, Name "Parameters/nyl"}, nyu = {100, Name "Parameters/nyu"},
  bump = {0.02, Name "Parameters/bump"}, grow = {1.025, Name "Parameters/grow"} ];
Point(1) = {-lu, 1, 0}; Point(2) = {0, 1, 0}; Point(3) = {ld, 1, 0};
Point(4) = {-lu, 9, 0}; Point(5) = {0, 9, 0}; Point(6) = {ld, 9, 0};
Point(7) = {0, 0, 0};   Point(8) = {ld, 0, 0};
Line(1) = {1, 2}; Line(2) = {2, 3};          // y = 1: upstream wall, shear-layer line
Line(3) = {4, 5}; Line(4) = {5, 6};          // top wall
Line(5) = {7, 8};                            // bottom wall
Line(6) = {1, 4}; Line(7) = {2, 5}; Line(8) = {3, 6}; // across the upper channel
Line(9) = {7, 2}; Line(10) = {8, 3};         // across the step's height
Curve Loop(1) = {1, 7, -3, -6}; Plane Surface(1) = {1}; // upstream channel
Curve Loop(2) = {2, 8, -4, -7}; Plane Surface(2) = {2}; // downstream, above the step's top
Curve Loop(3) = {5, 10, -2, -9}; Plane Surface(3) = {3}; // downstream, below it
Transfinite Curve{1, 3} = nxu + 1 Using Progression 1 / grow;
Transfinite Curve{2, 4, 5} = nxd + 1 Using Progression grow;
Transfinite Curve{6, 7, 8} = nyu + 1 Using Bump bump;
Transfinite Curve{9, 10} = nyl + 1 Using Bump 2.5 * bump;
Transfinite Surface{1, 2, 3};
Recombine Surface{1, 2, 3};
Physical Surface("fluid") = {1, 2, 3};
Physical Curve("inlet") = {6};
Physical Curve("outlet") = {8, 10};
Physical Curve("bottom") = {5};
Physical Curve("step") = {9};
Physical Curve("upstream_bottom") = {1};
Physical Curve("top") = {3, 4};
