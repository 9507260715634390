// Verification geometry: an infinitely long, uniformly magnetised circular cylinder (radius a) in a
// large air domain (radius R). With mu_r = 1 the field inside is uniform, B = B_r/2. mm.
SetFactory("OpenCASCADE");
DefineConstant[ a = {5, Name "Parameters/a"}, R = {150, Name "Parameters/R"}, h = {0.5, Name "Parameters/h"} ];
m = newv; Disk(m) = {0, 0, 0, a};
d = newv; Disk(d) = {0, 0, 0, R};
all() = BooleanFragments{ Surface{d}; Delete; }{ Surface{m}; Delete; };
sMag() = Surface In BoundingBox{-a - 1e-3, -a - 1e-3, -1, a + 1e-3, a + 1e-3, 1};
sAll() = Surface{:};
sAir() = sAll(); sAir() -= sMag();
Physical Surface("magnet", 1) = {sMag()};
Physical Surface("air", 2) = {sAir()};
cOuter() = CombinedBoundary{ Surface{sAll()}; };
Physical Curve("outer", 1) = {Abs(cOuter())};
bMag() = Boundary{ Surface{sMag()}; };
Field[1] = Distance; Field[1].EdgesList = {bMag()}; Field[1].NNodesByEdge = 400;
Field[2] = Threshold; Field[2].InField = 1; Field[2].LcMin = h; Field[2].LcMax = R/10;
Field[2].DistMin = 0; Field[2].DistMax = R;
Background Field = 2;
Mesh.CharacteristicLengthExtendFromBoundary = 0; Mesh.CharacteristicLengthFromPoints = 0;
Mesh.CharacteristicLengthFromCurvature = 0;
Mesh.Algorithm = 6; Mesh.RecombineAll = 1; Mesh.RecombinationAlgorithm = 1; Mesh.SubdivisionAlgorithm = 1;
