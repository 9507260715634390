# Helper functions shared by the module CMakeLists.

# servodrift::dealii: deal.II's headers as SYSTEM includes (so that -Wall -Wextra stay about our code),
# its release library and its definitions, without deal.II's own global compiler flags.
function(servodrift_dealii_interface)
  if(NOT DEAL_II_TARGET_CONFIG_INCLUDED)
    include(${DEAL_II_TARGET_CONFIG})
  endif()
  add_library(servodrift_dealii INTERFACE)
  target_include_directories(servodrift_dealii SYSTEM INTERFACE ${DEAL_II_INCLUDE_DIRS})
  target_link_libraries(servodrift_dealii INTERFACE ${DEAL_II_TARGET_RELEASE})
  target_compile_definitions(servodrift_dealii INTERFACE
    ${DEAL_II_USER_DEFINITIONS} ${DEAL_II_USER_DEFINITIONS_RELEASE})
  add_library(servodrift::dealii ALIAS servodrift_dealii)
endfunction()

# servodrift_module(name SOURCES ... LIBS ...): one static library per module, include root = project root.
function(servodrift_module name)
  cmake_parse_arguments(ARG "" "" "SOURCES;LIBS" ${ARGN})
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_LIBS})
endfunction()

# servodrift_embed(target NAME file): compiles the text of `file' into `target' as
# servodrift::embedded::NAME (regenerated when the file changes).
function(servodrift_embed target name file)
  set(out ${CMAKE_CURRENT_BINARY_DIR}/embedded_${name}.cc)
  add_custom_command(OUTPUT ${out}
    COMMAND ${CMAKE_COMMAND} -DINPUT=${file} -DOUTPUT=${out} -DNAME=${name} -P ${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake
    DEPENDS ${file} ${PROJECT_SOURCE_DIR}/cmake/EmbedText.cmake
    COMMENT "embedding ${file}")
  target_sources(${target} PRIVATE ${out})
endfunction()
