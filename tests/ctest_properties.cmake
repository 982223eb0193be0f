# ctest properties of individual discovered tests, applied after gtest_discover_tests' list
# (grpvss_tests_TESTS). Time limits live here, never in assertions (docs/reliability.md).
# Tests that take 20 s or more under ASan + UBSan on the 2-core CI machine (measured 2026-11-27,
# seconds beside each): Release only, so that the sanitizer suite fits CI's time
# (docs/reliability.md#ci-time). Each suite here keeps at least one test under the sanitizers
# that runs the same code on a smaller case (e.g. PandaCell.AClearPathIsClear..., Ur5eShard0).
set(GRPVSS_RELEASE_ONLY_TESTS
  BatchProgram.AStartAndThesisModeGiveVerifysOutputs  # 22 s
  BatchProgram.ReportsCertificatesAndResultLinesAreThoseOfVerifyProgram  # 46 s
  BatchTrajectory.ReportsCertificatesAndResultLinesAreThoseOfVerifyTrajectory  # 48 s
  CellCli.AUr5eFoldingItsWristIntoItsUpperArmIsASelfCollisionNamingBothLinks  # 40 s
  CellProbe.ALooseTermIsProvenOnItsKeptNormalWhileItKeepsMostOfItsLastClosestBound  # 30 s
  CertifiedQuery.NearContactAndExactTouchingAgreeWithExact  # 28 s
  ClaimMotionSelfPair.TheHandPassingWithinTheToleranceOfTheUpperArmIsWithinTolerance  # 81 s
  ClaimMotionSelfPair.WithTheClaimStepsTheGrazingFoldIsClear  # 68 s
  ClaimMotionSelfPairCli.TheSummaryAndTheJsonNameBothLinksOfThePair  # 45 s
  ClassifyExact.AgreesWithReferenceOnNearContactWherePlainDoubleFails  # 42 s
  ConfigurationCheck.AVerdictProbeFindsWhatTheClearanceProbeFindsOnSlabsThatHoldExactly  # 32 s
  ConfigurationCheck.NoConfigurationTheOracleFindsInContactIsClear  # 59 s
  InterferencePoints.NonEmptyExactlyWhenNotSeparatedAndPointsLieInBoth  # 59 s
  JointTrajectoryCli.ACertificateCheckedWithAnotherTrajectoryOrTamperedIsRejected  # 28 s
  LemmaAxisDistanceAlongStep.SampledAxisDistancesStayWithinTheStepRadius  # 30 s
  LemmaAxisDistanceAlongStep.TheCheckerAcceptsTheStepBoundAndRejectsOneBelowIt  # 94 s
  LemmaInterferenceCompleteness.SatAgreesWithEdgeFaceOrVertexOnRandomBoxes  # 26 s
  PandaCell.APanelThreeMillimetresAboveTheArmGrazesIt  # 63 s
  PandaCell.APathIntoTheShelfIsACollisionOfTheHandWithTheShelf  # 58 s
  PandaSelfCollision.FoldingTheHandIntoTheUpperArmIsACollisionNamingBothLinks  # 75 s
  PandaSelfCollision.TheFoldStoppedShortIsClearAndItsCertificateIsAccepted  # 56 s
  ProgramCli.AMovelAndItsEquivalentCpLinePathGiveTheSameCollision  # 24 s
  RelativeMotionLemma.InLinkAsFrameHullBTravelsAtMostItsBoundOverTheJointsBetween  # 175 s
  RevolutionRouteLemma.TheExactDistanceKeepsHalfTheSlackAlongStepsTheRouteProves  # 53 s
  SelfCollision.ACertificateWithAnotherPairListOrAFalseSlabIsRejected  # 44 s
  SelfCollision.AnExactReferenceAgreesOnRandomUr5ePaths  # 230 s
  SelfCollision.FoldingTheWristIntoTheUpperArmIsACollisionNamingBothLinks  # 43 s
  SeparationWitness.RandomWitnessesAreSoundTightAndTamperEvident  # 49 s
  StartCli.CheckCertificateAcceptsTheSameStartAndRejectsOrRefusesAnother  # 24 s
  UrdfOracleSoundness.TheHullAndSelfPairBoundsCoverTheMeasuredPaths  # 37 s
  UrdfOracleSoundness.TheMotionBoundCoversEveryHullPointsPath  # 26 s
  UserGuideExamples.EveryExampleExitsAsDocumented  # 28 s
  VertexRouteLemma.TheExactDistanceKeepsTheGapAlongStepsTheVertexBoundProves  # 36 s
  YamlPathCli.APoseTargetInTheWorldOrTheBaseEndsWhereTheJointsWere  # 57 s
)

foreach(test IN LISTS grpvss_tests_TESTS)
  list(FIND GRPVSS_RELEASE_ONLY_TESTS "${test}" release_only_index)  # (no IN_LIST: ctest's script mode)
  if(release_only_index GREATER -1)
    set_tests_properties("${test}" PROPERTIES LABELS heavy)
  endif()
  if(test MATCHES "^AbsurdInput\\.")
    # Absurd inputs must fail fast: seconds, even under the sanitizers on a loaded machine.
    set_tests_properties("${test}" PROPERTIES TIMEOUT 30)
  elseif(test STREQUAL "BatchMemory.TenThousandJobsStayUnder500MBAndAgreeWithVerify")
    # 10,000 verifications (~11 s on 2 cores): a resident-memory bound means nothing under the
    # sanitizers (shadow memory, quarantine), so Release only, like ResourceBounds.
    set_tests_properties("${test}" PROPERTIES TIMEOUT 900 LABELS heavy)
  elseif(test MATCHES "^ResourceBounds\\.")
    # The 10,000-obstacle, 100,000-step run: Release only (the sanitizer suite skips the label).
    set_tests_properties("${test}" PROPERTIES TIMEOUT 300 LABELS heavy)
  elseif(test MATCHES "^OracleSoundness\\.(RandomPtp|ScaraCp)Shard[1-9]")
    set_tests_properties("${test}" PROPERTIES LABELS heavy)  # shard 0 also runs under ASan
  elseif(test MATCHES "^UrdfOracleSoundness\\.(Ur5eShard[1-9]|PandaShard[0-9])")
    # Meshes of up to ~1,000 vertices: Release only (Ur5eShard0 also runs under ASan, fewer cases).
    set_tests_properties("${test}" PROPERTIES TIMEOUT 600 LABELS heavy)
  elseif(test STREQUAL "MotionClearance.TheVerifiersBoundsHoldOnTheOracleCells")
    set_tests_properties("${test}" PROPERTIES LABELS heavy)  # exact distances: Release only
  elseif(test MATCHES "^(NumericIk\\.RoundTripPuma560|CertifiedQuery\\.RandomSeparatedAndOverlappingPairsAgreeWithExact|MotionClearance\\.TheVerifiersBoundsHoldAlongTheNearMissMotion|ClassifyExact\\.AgreesWithIndependentReferenceOnRandomPairs|TrajectoryCli\\.EveryIkChoiceGivesTheSampleEndJoints)$")
    # The slowest numeric property tests (1.5-3 min each under the sanitizers): they test
    # numbers, which the Release suite covers; ASan and UBSan are for memory and UB, which
    # the many small tests of the same code exercise (docs/reliability.md#ci-time).
    set_tests_properties("${test}" PROPERTIES LABELS heavy)
  endif()
endforeach()

# A renamed test must not slip back under the sanitizers' clock unnoticed.
foreach(test IN LISTS GRPVSS_RELEASE_ONLY_TESTS)
  list(FIND grpvss_tests_TESTS "${test}" discovered_index)
  if(discovered_index EQUAL -1 AND NOT "${grpvss_tests_TESTS}" STREQUAL "")
    message(FATAL_ERROR "tests/ctest_properties.cmake: GRPVSS_RELEASE_ONLY_TESTS names ${test}, which is not a test")
  endif()
endforeach()
