# featloc_set_warnings(<target>): the same warning flags for every target.
function(featloc_set_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic)
endfunction()
