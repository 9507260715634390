# write_if_changed(FILE CONTENT): rewrites FILE only when CONTENT differs, so that a rebuild without a
# real change recompiles nothing.
function(write_if_changed file content)
  set(old "")
  if(EXISTS ${file})
    file(READ ${file} old)
  endif()
  if(NOT old STREQUAL content)
    file(WRITE ${file} "${content}")
  endif()
endfunction()
