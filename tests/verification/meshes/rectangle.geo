// Verification geometry: the rectangle [x0, x1] x [y0, y1] (a channel, a pipe in x-r, a cavity, the
// gap between two discs), nx x ny cells, quadrilaterals (tri = 0, structured, optionally graded
// towards y0 and y1 by `bump') or triangles (tri = 1, unstructured, about the same size).
// Boundaries: left, right, bottom, top.
DefineConstant[ x0 = {0, Name "Parameters/x0"}, x1 = {1, Name "Parameters/x1"},
  y0 = {0, Name "Parameters/y0"}, y1 = {1, Name "Parameters/y1"},
  nx = {10, Name "Parameters/nx"}, ny = {10, Name "Parameters/ny"},
  bump = {1, Name "Parameters/bump"}, tri = {0, Name "Parameters/tri"} ];
h = (y1 - y0) / ny;
Point(1) = {x0, y0, 0, h}; Point(2) = {x1, y0, 0, h}; Point(3) = {x1, y1, 0, h}; Point(4) = {x0, y1, 0, h};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
If (tri == 0)
  Transfinite Curve{1, 3} = nx + 1;
  If (bump == 1)
    Transfinite Curve{2, 4} = ny + 1;
  Else
    Transfinite Curve{2} = ny + 1 Using Bump bump;
    Transfinite Curve{4} = ny + 1 Using Bump bump;
  EndIf
  Transfinite Surface{1};
  Recombine Surface{1};
Else
  Mesh.Algorithm = 6;
  Mesh.CharacteristicLengthMax = h;
EndIf
Physical Surface("fluid") = {1};
Physical Curve("bottom") = {1};
Physical Curve("right") = {2};
Physical Curve("top") = {3};
Physical Curve("left") = {4};
