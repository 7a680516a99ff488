# The fast test tier, ctest label `unit`: the quick tests of core (scene loading, output), of the
# compare layer (metrics, oracles, report helpers) and the error paths of the app. Read by ctest
# after the discovered tests (their lists are test_core_TESTS, ...); run with `ctest -L unit`.
# Left out: anything that runs engines for seconds (test_dem, test_engines, the study end to end,
# validate end to end).
foreach(t IN LISTS test_core_TESTS test_fuzz_TESTS)
  set_tests_properties("${t}" PROPERTIES LABELS unit)
endforeach()
foreach(t IN LISTS test_compare_TESTS)
  if(NOT t MATCHES "study: |metacharacters")
    set_tests_properties("${t}" PROPERTIES LABELS unit)
  endif()
endforeach()
foreach(t IN LISTS test_app_TESTS)
  if(t MATCHES "refuse|reject|bad scene|unknown|fails when|--version|cairn list|cairn make")
    set_tests_properties("${t}" PROPERTIES LABELS unit)
  endif()
endforeach()
