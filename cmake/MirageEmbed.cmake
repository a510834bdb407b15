# Embeds text files (GLSL sources and the C++/GLSL shared headers) into the binary, keyed by
# their path relative to src/, so that `mirage` runs from anywhere with no shader directory.
set(MIRAGE_EMBED_SCRIPT ${CMAKE_CURRENT_LIST_DIR}/embed_files.cmake)

function(mirage_embed_files out_cpp base_dir)
  set(files ${ARGN})
  set(manifest ${out_cpp}.files)
  string(REPLACE ";" "\n" lines "${files}")
  file(CONFIGURE OUTPUT ${manifest} CONTENT "${lines}\n")
  add_custom_command(
    OUTPUT ${out_cpp}
    COMMAND ${CMAKE_COMMAND} -DOUTPUT=${out_cpp} -DBASE_DIR=${base_dir} -DMANIFEST=${manifest}
            -P ${MIRAGE_EMBED_SCRIPT}
    DEPENDS ${files} ${manifest} ${MIRAGE_EMBED_SCRIPT}
    COMMENT "Embedding shader sources"
    VERBATIM)
endfunction()
