# SPDX-License-Identifier: Apache-2.0
# The library is one static library per folder of lib/ ("layer"), declared bottom-up in
# lib/CMakeLists.txt. Each lib/<layer>/CMakeLists.txt lists its sources and the layers
# it builds on:
#
#   strielad_layer(<name> [FOLDER <folder>]
#     SOURCES <file.cpp>...             relative to lib/<folder> (default: lib/<name>)
#     [DEPENDS <layer>...]              layers declared before this one
#     [PUBLIC_LIBS <target>...]         third-party libraries its headers need
#     [PRIVATE_LIBS <target>...])       third-party libraries only its sources need
#
# makes the target strielad_<name> (alias strielad::<name>, exported as
# strielad::<name>). A layer may include headers only from itself and from the layers
# it depends on, directly or through them; strielad_check_layers() at the end of
# lib/CMakeLists.txt refuses, at configure time, a file that includes from any other
# folder, and a .cpp in a layer folder that no layer lists. Since DEPENDS can only name
# layers declared earlier, the layers cannot form a cycle.

set(STRIELAD_LIB_DIR ${PROJECT_SOURCE_DIR}/lib)
set(STRIELAD_GENERATED_DIR ${PROJECT_BINARY_DIR}/lib/generated)

function(strielad_layer name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "" "FOLDER" "SOURCES;DEPENDS;PUBLIC_LIBS;PRIVATE_LIBS")
  if(arg_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "strielad_layer(${name}): unknown arguments ${arg_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT arg_FOLDER)
    set(arg_FOLDER ${name})
  endif()
  set(target strielad_${name})

  # Reach: the folders this layer may include from.
  set(reach ${arg_FOLDER})
  foreach(dep IN LISTS arg_DEPENDS)
    get_property(dep_reach GLOBAL PROPERTY STRIELAD_REACH_${dep})
    if(NOT dep_reach)
      message(FATAL_ERROR "lib/${arg_FOLDER}/CMakeLists.txt: layer ${name} depends on "
                          "'${dep}', which is not declared before it in lib/CMakeLists.txt")
    endif()
    list(APPEND reach ${dep_reach})
  endforeach()
  list(REMOVE_DUPLICATES reach)
  set_property(GLOBAL PROPERTY STRIELAD_REACH_${name} ${reach})
  set_property(GLOBAL APPEND PROPERTY STRIELAD_LAYERS ${name})
  set_property(GLOBAL PROPERTY STRIELAD_FOLDER_${name} ${arg_FOLDER})

  list(TRANSFORM arg_SOURCES PREPEND ${STRIELAD_LIB_DIR}/${arg_FOLDER}/)
  set_property(GLOBAL APPEND PROPERTY STRIELAD_SOURCES_${arg_FOLDER} ${arg_SOURCES})

  add_library(${target} STATIC ${arg_SOURCES})
  add_library(strielad::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${name})
  target_include_directories(${target} PUBLIC
    $<BUILD_INTERFACE:${STRIELAD_LIB_DIR}>
    $<BUILD_INTERFACE:${STRIELAD_GENERATED_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}/strielad>)
  list(TRANSFORM arg_DEPENDS PREPEND strielad_ OUTPUT_VARIABLE dep_targets)
  target_link_libraries(${target} PUBLIC ${dep_targets} ${arg_PUBLIC_LIBS}
                                  PRIVATE ${arg_PRIVATE_LIBS})
  strielad_warnings(${target})
  # GCC 12 vectorizes the per-sample loops (statistics, masking, sub-sampling) only at
  # -O3. Scoped to the library: at -O3 GCC 12 also emits false -Wrestrict warnings on
  # std::string code (PR 105651) that the tests are full of.
  if(NOT STRIELAD_FUZZ_ONLY)
    target_compile_options(${target} PRIVATE $<$<CONFIG:RelWithDebInfo,Release>:-O3>)
  endif()
  # Every product rounded on its own, as the default x86-64 build does: where the target
  # has FMA (-march=native on current x86, any aarch64) GCC would fuse multiply-adds, and
  # the same edge crossing would get other bits than in a default build (measured: 183 of
  # 200 cloud bricks' meshes differed), so nodes extracted by differently built binaries
  # would not meet at bit-identical vertices. PUBLIC: the header-inline kernel code (edge
  # crossings) compiled into tools and tests follows the same rule.
  target_compile_options(${target} PUBLIC -ffp-contract=off)
endfunction()

# The folders a file of lib/<folder> includes from ("#include "<folder>/...").
function(strielad_included_folders file out_var)
  file(STRINGS ${file} lines REGEX "^[ \t]*#[ \t]*include[ \t]+\"[a-z_]+/")
  set(folders)
  foreach(line IN LISTS lines)
    string(REGEX REPLACE "^[ \t]*#[ \t]*include[ \t]+\"([a-z_]+)/.*$" "\\1" folder "${line}")
    list(APPEND folders ${folder})
  endforeach()
  list(REMOVE_DUPLICATES folders)
  set(${out_var} ${folders} PARENT_SCOPE)
endfunction()

function(strielad_check_layers)
  get_property(layers GLOBAL PROPERTY STRIELAD_LAYERS)
  set(folders)
  foreach(layer IN LISTS layers)
    get_property(folder GLOBAL PROPERTY STRIELAD_FOLDER_${layer})
    get_property(reach GLOBAL PROPERTY STRIELAD_REACH_${layer})
    list(APPEND folders ${folder})
    # A folder's reach: the union of its layers' (lib/serve holds serve and serve_mpi).
    list(APPEND folder_reach_${folder} ${reach})
  endforeach()
  list(REMOVE_DUPLICATES folders)
  set(problems)
  foreach(folder IN LISTS folders)
    get_property(listed GLOBAL PROPERTY STRIELAD_SOURCES_${folder})
    file(GLOB folder_files CONFIGURE_DEPENDS
         ${STRIELAD_LIB_DIR}/${folder}/*.cpp ${STRIELAD_LIB_DIR}/${folder}/*.h)
    foreach(file IN LISTS folder_files)
      file(RELATIVE_PATH shown ${PROJECT_SOURCE_DIR} ${file})
      if(file MATCHES "\\.cpp$" AND NOT file IN_LIST listed)
        list(APPEND problems "${shown} is not listed in lib/${folder}/CMakeLists.txt")
      endif()
      strielad_included_folders(${file} included)
      foreach(inc IN LISTS included)
        if(NOT inc IN_LIST folder_reach_${folder})
          list(APPEND problems
               "${shown} includes from lib/${inc}/, which layer ${folder} does not build on "
               "(DEPENDS in lib/${folder}/CMakeLists.txt: a layer includes only downwards)")
        endif()
      endforeach()
    endforeach()
  endforeach()
  if(problems)
    list(JOIN problems "\n  " text)
    message(FATAL_ERROR "Layering:\n  ${text}")
  endif()
endfunction()
