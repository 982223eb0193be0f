# ctest properties of individual discovered tests, applied after gtest_discover_tests' list
# (grpvss_tests_TESTS). Time limits live here, never in assertions (docs/reliability.md).
foreach(test IN LISTS grpvss_tests_TESTS)
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
