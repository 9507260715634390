// Planar cross-section of the torque motor (model.md 4.1, D10): the right half (x >= 0); servodrift
// mirrors the mesh about x = 0, so that the mesh of the whole motor is exactly symmetric.
//
// Coordinates in mm, origin at the armature pivot (the armature's centre), x along the armature,
// y up across the gaps. servodrift sets every parameter below through the gmsh SDK (ONELAB names
// "Parameters/<name>") from the valve description at the temperature of the case; the defaults here
// are RV-1 at 40 degC, so that `gmsh torque_motor.geo' shows the motor.
//
// Parts (physical surfaces): armature (1J50), pole_pieces (1J50: lower plate with its tip, upper plate
// with its tip), magnet (the equivalent in-plane block of D10 at the outboard end, magnetised +y),
// coil_upper and coil_lower (the coil's two out-of-plane current regions above and below the arm),
// air_gap (the two working gaps of this side, structured), air (the rest, to a circle of radius R).
// Physical curves: outer (A_z = 0), symmetry_axis (x = 0, interior after mirroring).
//
// Stack-up (E6, E7), heights from the datum y = -Ha (the body face under the lower plate):
//   lower plate 0..tlow, lower pole face at Hc, magnet tlow..tlow+lm, upper plate above it,
//   upper pole face hp below the magnet seat; hence g_12 = Ha - Har/2 - Hc and
//   g_34 = tlow + lm - hp - Ha - Har/2.
SetFactory("OpenCASCADE");
DefineConstant[
  a = {14.8, Name "Parameters/a"},        // pivot to pole-face centre
  lp = {4.0, Name "Parameters/lp"},       // pole-face length along x
  Har = {3.0, Name "Parameters/Har"},     // armature thickness
  La = {33.6, Name "Parameters/La"},      // armature length
  Ha = {10.8, Name "Parameters/Ha"},      // datum to armature centre
  Hc = {9.0, Name "Parameters/Hc"},       // datum to lower pole face
  tlow = {3.0, Name "Parameters/tlow"},   // lower plate thickness (H_c')
  lm = {12.0, Name "Parameters/lm"},      // magnet length (height)
  hp = {2.4, Name "Parameters/hp"},       // upper pole-tip protrusion below the magnet seat
  tup = {3.0, Name "Parameters/tup"},     // upper plate thickness
  xm = {19.0, Name "Parameters/xm"},      // inner edge of the magnet block
  wm = {6.25, Name "Parameters/wm"},      // width of the magnet block
  cin = {3.0, Name "Parameters/cin"},     // coil window from x = cin ...
  cout = {11.0, Name "Parameters/cout"},  // ... to x = cout
  cclear = {0.2, Name "Parameters/cclear"}, // coil clearance from the armature
  ch = {2.0, Name "Parameters/ch"},       // coil height
  R = {60, Name "Parameters/R"},          // radius of the air domain
  nlayers = {8, Name "Parameters/nlayers"}, // element layers across each working gap
  hgap = {0.15, Name "Parameters/hgap"},  // element size along the gaps and near the armature
  hiron = {0.6, Name "Parameters/hiron"}, // element size at the other parts
  hmax = {15, Name "Parameters/hmax"}     // element size at the outer boundary
];
glow = Ha - Har/2 - Hc;
gup = tlow + lm - hp - Ha - Har/2;
ydat = -Ha; ylt = ydat + tlow; ylf = ydat + Hc; ymag = ylt + lm; yuf = ymag - hp; ytop = ymag + tup;
xe = xm + wm;
If (glow <= 0 || gup <= 0)
  Error("closed working gap: glow = %g, gup = %g mm", glow, gup);
EndIf

arm = newv; Rectangle(arm) = {0, -Har/2, 0, La/2, Har};
plow = newv; Rectangle(plow) = {0, ydat, 0, xe, tlow};
tiplow = newv; Rectangle(tiplow) = {a - lp/2, ylt, 0, lp, ylf - ylt};
mag = newv; Rectangle(mag) = {xm, ylt, 0, wm, lm};
pup = newv; Rectangle(pup) = {0, ymag, 0, xe, tup};
tipup = newv; Rectangle(tipup) = {a - lp/2, yuf, 0, lp, ymag - yuf};
gl = newv; Rectangle(gl) = {a - lp/2, ylf, 0, lp, glow};
gu = newv; Rectangle(gu) = {a - lp/2, Har/2, 0, lp, gup};
cu = newv; Rectangle(cu) = {cin, Har/2 + cclear, 0, cout - cin, ch};
cl = newv; Rectangle(cl) = {cin, -Har/2 - cclear - ch, 0, cout - cin, ch};
d = newv; Disk(d) = {0, 0, 0, R};
h = newv; Rectangle(h) = {-R - 1, -R - 1, 0, R + 1, 2*R + 2};
half = newv; BooleanDifference(half) = { Surface{d}; Delete; }{ Surface{h}; Delete; };
lowpole() = BooleanUnion{ Surface{plow}; Delete; }{ Surface{tiplow}; Delete; };
uppole() = BooleanUnion{ Surface{pup}; Delete; }{ Surface{tipup}; Delete; };
all() = BooleanFragments{ Surface{half}; Delete; }{ Surface{arm, lowpole(), uppole(), mag, gl, gu, cu, cl}; Delete; };

eps = 1e-3;
sArm() = Surface In BoundingBox{-eps, -Har/2 - eps, -1, La/2 + eps, Har/2 + eps, 1};
sLow() = Surface In BoundingBox{-eps, ydat - eps, -1, xe + eps, ylf + eps, 1};
sUp() = Surface In BoundingBox{-eps, yuf - eps, -1, xe + eps, ytop + eps, 1};
sMag() = Surface In BoundingBox{xm - eps, ylt - eps, -1, xe + eps, ymag + eps, 1};
sLow() -= sMag(); sUp() -= sMag();
sGl() = Surface In BoundingBox{a - lp/2 - eps, ylf - eps, -1, a + lp/2 + eps, -Har/2 + eps, 1};
sGu() = Surface In BoundingBox{a - lp/2 - eps, Har/2 - eps, -1, a + lp/2 + eps, yuf + eps, 1};
sCu() = Surface In BoundingBox{cin - eps, Har/2 + cclear - eps, -1, cout + eps, Har/2 + cclear + ch + eps, 1};
sCl() = Surface In BoundingBox{cin - eps, -Har/2 - cclear - ch - eps, -1, cout + eps, -Har/2 - cclear + eps, 1};
sAll() = Surface{:};
sAir() = sAll();
sAir() -= sArm(); sAir() -= sLow(); sAir() -= sUp(); sAir() -= sMag();
sAir() -= sGl(); sAir() -= sGu(); sAir() -= sCu(); sAir() -= sCl();

Physical Surface("armature", 1) = {sArm()};
Physical Surface("pole_pieces", 2) = {sLow(), sUp()};
Physical Surface("magnet", 3) = {sMag()};
Physical Surface("coil_upper", 4) = {sCu()};
Physical Surface("coil_lower", 5) = {sCl()};
Physical Surface("air", 6) = {sAir()};
Physical Surface("air_gap", 7) = {sGl(), sGu()};
cAxis() = Curve In BoundingBox{-eps, -R - eps, -1, eps, R + eps, 1};
cOuter() = CombinedBoundary{ Surface{sAll()}; };
cOuter() = Abs(cOuter());
cOuter() -= cAxis();
Physical Curve("outer", 1) = {cOuter()};
Physical Curve("symmetry_axis", 2) = {cAxis()};

// The working gaps: structured quadrilaterals, nlayers across, about hgap along.
nalong = Ceil(lp / hgap);
For side In {0:1}
  yb = (side == 0) ? ylf : Har/2;
  yt = (side == 0) ? -Har/2 : yuf;
  horizontal() = Curve In BoundingBox{a - lp/2 - eps, yb - eps, -1, a + lp/2 + eps, yb + eps, 1};
  horizontal() += Curve In BoundingBox{a - lp/2 - eps, yt - eps, -1, a + lp/2 + eps, yt + eps, 1};
  vertical() = Curve In BoundingBox{a - lp/2 - eps, yb - eps, -1, a - lp/2 + eps, yt + eps, 1};
  vertical() += Curve In BoundingBox{a + lp/2 - eps, yb - eps, -1, a + lp/2 + eps, yt + eps, 1};
  Transfinite Curve{horizontal()} = nalong + 1;
  Transfinite Curve{vertical()} = nlayers + 1;
EndFor
Transfinite Surface{sGl(), sGu()};
Recombine Surface{sGl(), sGu()};

// Sizes: hgap at the gaps and the armature, hiron at the other parts, growing linearly with the
// distance to hmax at the outer boundary (the far field decays like a 2D dipole's).
bGap() = Boundary{ Surface{sGl(), sGu(), sArm()}; };
Field[1] = Distance; Field[1].EdgesList = {bGap()}; Field[1].NNodesByEdge = 200;
Field[2] = Threshold; Field[2].InField = 1; Field[2].LcMin = hgap; Field[2].LcMax = hmax;
Field[2].DistMin = 0.5; Field[2].DistMax = R;
bParts() = Boundary{ Surface{sLow(), sUp(), sMag(), sCu(), sCl()}; };
Field[3] = Distance; Field[3].EdgesList = {bParts()}; Field[3].NNodesByEdge = 200;
Field[4] = Threshold; Field[4].InField = 3; Field[4].LcMin = hiron; Field[4].LcMax = hmax;
Field[4].DistMin = 0; Field[4].DistMax = R;
Field[5] = Min; Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.CharacteristicLengthExtendFromBoundary = 0;
Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
// Frontal-Delaunay, recombined, then split into quadrilaterals only (deal.II needs an all-quad mesh).
// (Algorithm 8 crashes in Debian's gmsh 4.8.)
Mesh.Algorithm = 6;
Mesh.RecombineAll = 1;
Mesh.RecombinationAlgorithm = 1;
Mesh.SubdivisionAlgorithm = 1;
