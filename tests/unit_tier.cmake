# The two test tiers, as ctest labels: `unit` (each test checks one source file, in seconds; run
# with `ctest -L unit`) and `physics` (scenes run through engines, end to end). Read by ctest after
# the discovered tests (their lists are test_core_TESTS, ...). Every discovered test gets one label.
#   unit: core, the fuzzer's regressions, the compare layer (but the studies and the scale bench end to end and the
#         report metacharacters run through engines), the dem engine's parts (test_dem_unit: the
#         files test_<file>.cpp of a backends/dem source file), the app's error paths
#   physics: the dem scenarios (test_dem), the reference engines, everything else end to end
# cairn_tier(LIST UNIT [EXCEPT]): the tests of LIST whose names match UNIT and not EXCEPT are unit
macro(cairn_tier tests unit_regex)
  set(except "${ARGN}")
  foreach(t IN LISTS ${tests})
    if(t MATCHES "${unit_regex}" AND (except STREQUAL "" OR NOT t MATCHES "${except}"))
      set_tests_properties("${t}" PROPERTIES LABELS unit)
    else()
      set_tests_properties("${t}" PROPERTIES LABELS physics)
    endif()
  endforeach()
endmacro()
cairn_tier(test_core_TESTS ".")
cairn_tier(test_fuzz_TESTS ".")
cairn_tier(test_dem_unit_TESTS ".")
cairn_tier(test_compare_TESTS "." "study: |metacharacters|bench scale --backends|bench scale --large")
cairn_tier(test_app_TESTS "refuse|reject|bad scene|unknown|fails when|--version|cairn list|cairn make" "then cairn compare")
cairn_tier(test_dem_TESTS "^$")       # no test name is empty: all physics
cairn_tier(test_engines_TESTS "^$")
