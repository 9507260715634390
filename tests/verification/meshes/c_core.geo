// Verification geometry: a U-shaped iron core with a coil on its yoke and an I-shaped keeper across
// two narrow gaps (a C-core electromagnet whose flux crosses two gaps in series). mm.
// Closed form (ideal iron, no fringing): B_gap = mu0 N I/(2 g), force on the keeper 2 B^2 A/(2 mu0).
SetFactory("OpenCASCADE");
DefineConstant[ g = {0.2, Name "Parameters/g"}, w = {10, Name "Parameters/w"}, R = {300, Name "Parameters/R"},
  hgap = {0.1, Name "Parameters/hgap"}, nlayers = {4, Name "Parameters/nlayers"} ];
W = 60; H = 40;          // core outer width and height
yoke = newv; Rectangle(yoke) = {-W/2, 0, 0, W, w};
legl = newv; Rectangle(legl) = {-W/2, w, 0, w, H - w};
legr = newv; Rectangle(legr) = {W/2 - w, w, 0, w, H - w};
core() = BooleanUnion{ Surface{yoke}; Delete; }{ Surface{legl, legr}; Delete; };
keeper = newv; Rectangle(keeper) = {-W/2, H + g, 0, W, w};
gl = newv; Rectangle(gl) = {-W/2, H, 0, w, g};
gr = newv; Rectangle(gr) = {W/2 - w, H, 0, w, g};
ci = newv; Rectangle(ci) = {-12, w + 1, 0, 24, 6};   // coil side in the window
co = newv; Rectangle(co) = {-12, -7, 0, 24, 6};       // coil side under the yoke
d = newv; Disk(d) = {0, 20, 0, R};
all() = BooleanFragments{ Surface{d}; Delete; }{ Surface{core(), keeper, gl, gr, ci, co}; Delete; };
eps = 1e-3;
sCore() = Surface In BoundingBox{-W/2 - eps, -eps, -1, W/2 + eps, H + eps, 1};
sKeeper() = Surface In BoundingBox{-W/2 - eps, H + g - eps, -1, W/2 + eps, H + g + w + eps, 1};
sGap() = Surface In BoundingBox{-W/2 - eps, H - eps, -1, W/2 + eps, H + g + eps, 1};
sCi() = Surface In BoundingBox{-12 - eps, w + 1 - eps, -1, 12 + eps, w + 7 + eps, 1};
sCo() = Surface In BoundingBox{-12 - eps, -7 - eps, -1, 12 + eps, -1 + eps, 1};
sCore() -= sCi(); sCore() -= sCo(); sCore() -= sGap();
window() = Surface In BoundingBox{-W/2 + w - eps, w - eps, -1, W/2 - w + eps, H + eps, 1};
window() -= sCi();
sCore() -= window();
sAll() = Surface{:};
sAir() = sAll(); sAir() -= sCore(); sAir() -= sKeeper(); sAir() -= sGap(); sAir() -= sCi(); sAir() -= sCo();
Physical Surface("core", 1) = {sCore()};
Physical Surface("keeper", 2) = {sKeeper()};
sGapL() = Surface In BoundingBox{-W/2 - eps, H - eps, -1, -W/2 + w + eps, H + g + eps, 1};
sGapR() = sGap(); sGapR() -= sGapL();
Physical Surface("gap_left", 3) = {sGapL()};
Physical Surface("gap_right", 7) = {sGapR()};
Physical Surface("coil_in", 4) = {sCi()};
Physical Surface("coil_out", 5) = {sCo()};
Physical Surface("air", 6) = {sAir()};
cOuter() = CombinedBoundary{ Surface{sAll()}; };
Physical Curve("outer", 1) = {Abs(cOuter())};
// the two gaps: structured, nlayers across
xs() = {-W/2, W/2 - w};
For k In {0:1}
  x0 = xs(k);
  horizontal() = Curve In BoundingBox{x0 - eps, H - eps, -1, x0 + w + eps, H + eps, 1};
  horizontal() += Curve In BoundingBox{x0 - eps, H + g - eps, -1, x0 + w + eps, H + g + eps, 1};
  vertical() = Curve In BoundingBox{x0 - eps, H - eps, -1, x0 + eps, H + g + eps, 1};
  vertical() += Curve In BoundingBox{x0 + w - eps, H - eps, -1, x0 + w + eps, H + g + eps, 1};
  Transfinite Curve{horizontal()} = Ceil(w / hgap) + 1;
  Transfinite Curve{vertical()} = nlayers + 1;
EndFor
Transfinite Surface{sGap()};
bGap() = Boundary{ Surface{sGap()}; };
bParts() = Boundary{ Surface{sCore(), sKeeper(), sCi(), sCo()}; };
Field[1] = Distance; Field[1].EdgesList = {bGap()}; Field[1].NNodesByEdge = 200;
Field[2] = Threshold; Field[2].InField = 1; Field[2].LcMin = hgap; Field[2].LcMax = R/10;
Field[2].DistMin = 1; Field[2].DistMax = R;
Field[3] = Distance; Field[3].EdgesList = {bParts()}; Field[3].NNodesByEdge = 200;
Field[4] = Threshold; Field[4].InField = 3; Field[4].LcMin = 1.5; Field[4].LcMax = R/10;
Field[4].DistMin = 0; Field[4].DistMax = R;
Field[5] = Min; Field[5].FieldsList = {2, 4};
Background Field = 5;
Mesh.CharacteristicLengthExtendFromBoundary = 0; Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.Algorithm = 6; Mesh.RecombineAll = 1; Mesh.RecombinationAlgorithm = 1; Mesh.SubdivisionAlgorithm = 1;
