# The gtest cases that take 20 s or more on the 2-core machine: labelled `slow' as well (ctest
# includes this file after it has discovered the tests; tests/CMakeLists.txt).
foreach(name PilotFieldStage.OrificePathOverTemperatureKeepsTheAnswer Calibration.NoisyDataCoverTheTruth
             PilotField.MeshConvergence PilotField.FixedOrificeFollowsLichtarowiczWithKEpsilon
             PilotField.CaughtCyclesLeaveTheAnswerUnchanged PilotField.GridSequencingKeepsTheFineMeshAnswer
             PilotFieldStage.StalledLaminarCaseIsReportedByItsTimeAverage
             PilotFieldChain.SSTOrificeGoesOnFromKEpsilonWhereItDivergesAlone
             PilotFieldChain.LaunderSharmaHotNozzleConvergesFromRest
             TurbulenceValidation/BackwardFacingStep.ReattachmentLength/TwoLayer
             TurbulenceValidation/BackwardFacingStep.ReattachmentLength/SST
             TurbulenceValidation/BackwardFacingStep.ReattachmentLength/LaunderSharma
             TurbulenceValidation/ImpingingJet.WallJetProfiles/TwoLayer
             TurbulenceValidation/ImpingingJet.WallJetProfiles/SST
             TurbulenceValidation/ImpingingJet.WallJetProfiles/LaunderSharma
             TurbulenceValidation/SharpEdgedOrifice.Lichtarowicz/TwoLayer
             TurbulenceValidation/SharpEdgedOrifice.Lichtarowicz/SST
             TurbulenceValidation/CavitatingOrifice.Nurick/TwoLayer
             TurbulenceValidation/CavitatingOrifice.Nurick/SST
             TurbulenceValidation/CavitatingOrifice.Nurick/LaunderSharma)
  set_tests_properties(${name} PROPERTIES LABELS "verification;slow")
endforeach()
