# SPDX-License-Identifier: Apache-2.0
# -Wall -Wextra on every target of the project (-Werror with STRIELAD_WERROR).
function(strielad_warnings target)
  target_compile_options(${target} PRIVATE -Wall -Wextra)
  if(STRIELAD_WERROR)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()
