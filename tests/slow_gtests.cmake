# Labels `slow' the gtest cases whose source marks them SLOW_TEST or SLOW_TEST_P
# (tests/support/core_support.h). ctest includes this file after it has discovered the cases
# (tests/CMakeLists.txt), so the lists <target>_TESTS of gtest_discover_tests are set; the mark is
# read from the sources each time, so that a renamed or moved test keeps its label.
file(GLOB sources ${CMAKE_CURRENT_LIST_DIR}/unit/*.cc ${CMAKE_CURRENT_LIST_DIR}/verification/*.cc)
set(slow)
foreach(source ${sources})
  file(STRINGS ${source} marks REGEX "SLOW_TEST(_P)?\\(")
  foreach(mark ${marks})
    if(mark MATCHES "SLOW_TEST(_P)?\\( *([A-Za-z0-9_]+) *, *([A-Za-z0-9_]+) *\\)")
      list(APPEND slow "${CMAKE_MATCH_2}.${CMAKE_MATCH_3}")
    endif()
  endforeach()
endforeach()
# (ctest's script mode sets a test's properties only whole: the label of its program, then slow)
foreach(program unit verification)
  foreach(name ${${program}_tests_TESTS})
    # Prefix/Suite.Name/Parameter of a parameterised case: its Suite.Name
    string(REGEX REPLACE "^[A-Za-z0-9_]+/([A-Za-z0-9_]+\\.[A-Za-z0-9_]+)/.*$" "\\1" case ${name})
    list(FIND slow ${case} index)
    if(index GREATER -1)
      set_tests_properties(${name} PROPERTIES LABELS "${program};slow")
    endif()
  endforeach()
endforeach()
