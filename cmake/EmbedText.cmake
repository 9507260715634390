# Writes a .cc that defines `const char *NAME' with the contents of INPUT (a raw string literal), so
# that the executable carries its gmsh templates and needs no path to the source tree.
file(READ ${INPUT} text)
set(content "// generated from ${INPUT} by cmake/EmbedText.cmake\nnamespace servodrift::embedded {\nextern const char *const ${NAME};\nconst char *const ${NAME} = R\"sd_geo(${text})sd_geo\";\n}\n")
include(${CMAKE_CURRENT_LIST_DIR}/WriteIfChanged.cmake)
write_if_changed(${OUTPUT} "${content}")
