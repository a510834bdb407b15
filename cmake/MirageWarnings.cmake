# Warnings for mirage's own targets (third-party headers come in as SYSTEM through imported targets).
function(mirage_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor
                                           -Wcast-align -Wimplicit-fallthrough)
  if(MIRAGE_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
