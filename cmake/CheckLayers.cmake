# The include checker of the layer targets (cmake/Layers.cmake), run with cmake -P:
#   -DLAYERS=<build>/mb_layers.cmake   the graph, as configure read it from the targets
#   -DSOURCE_DIR=<compiler/>           check every #include "<folder>/..." of each folder's
#                                      .cpp/.hpp files: the folder must be its own or one its
#                                      target links directly; and each link must be used
#   -DDATA_DIR=<shaderlib/>            check every #include "<folder>/..." of the brick library's
#                                      .cpp/.hpp files (the double references): the data layer
#                                      sits below every layer but core/, so core/ is the only
#                                      folder of compiler/ it may include
#   -DSTAMP=<file>                     touched when the check passes (the build step's output)
#   -DDOC=<docs/architecture.md>       check that the doc's graph is the targets' graph; with
#   -DUPDATE_DOC=ON                    rewrite it instead
# A violation is one line, file:line:column: error: ..., and the script exits non-zero.
cmake_minimum_required(VERSION 3.25)
include(${CMAKE_CURRENT_LIST_DIR}/LayerGraph.cmake)
include(${LAYERS})

set(errors 0)
function(layer_error)
  string(JOIN "" text ${ARGV})
  message(NOTICE "${text}")
  math(EXPR count "${errors} + 1")
  set(errors ${count} PARENT_SCOPE)
endfunction()

# A file's quoted #include lines whose path starts with a folder ("<folder>/..."), and its
# content when it has any (fast path: system headers and plain names are never layers).
function(folder_includes file content_var lines_var)
  file(STRINGS ${file} includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"[a-z0-9_]+/")
  set(content "")
  if(includes)
    file(READ ${file} content)
  endif()
  set(${content_var} "${content}" PARENT_SCOPE)
  set(${lines_var} "${includes}" PARENT_SCOPE)
endfunction()

# The first folder of an #include line's path.
function(included_folder line folder_var)
  string(REGEX MATCH "\"([a-z0-9_]+)/[^\"]*\"" quoted "${line}")
  set(${folder_var} ${CMAKE_MATCH_1} PARENT_SCOPE)
endfunction()

# Where an #include line is in a file's content: its line (the text before it, counted in
# lines) and the column of its path.
function(include_location content line row_var column_var)
  string(FIND "${content}" "${line}" offset)
  string(SUBSTRING "${content}" 0 ${offset} before)
  string(REGEX MATCHALL "\n" newlines "${before}")
  list(LENGTH newlines row)
  math(EXPR row "${row} + 1")
  string(FIND "${line}" "\"" quote)
  math(EXPR column "${quote} + 2")
  set(${row_var} ${row} PARENT_SCOPE)
  set(${column_var} ${column} PARENT_SCOPE)
endfunction()

mb_layer_cycle(cycle)
if(cycle)
  layer_error("${LAYERS}: error: the layer targets form a cycle: ${cycle}")
endif()

if(SOURCE_DIR)
  set(folders ${MB_LAYER_FOLDERS} ${MB_LAYER_PROGRAM_FOLDERS})
  foreach(folder IN LISTS folders)
    set(allowed ${folder} ${MB_LAYER_DEPS_${folder}})
    set(used)
    file(GLOB files ${SOURCE_DIR}/${folder}/*.cpp ${SOURCE_DIR}/${folder}/*.hpp)
    list(SORT files)
    foreach(file IN LISTS files)
      folder_includes(${file} content includes)
      foreach(line IN LISTS includes)
        included_folder("${line}" included)
        if(NOT included IN_LIST folders)
          continue()
        endif()
        list(APPEND used ${included})
        if(included IN_LIST allowed)
          continue()
        endif()
        include_location("${content}" "${line}" row column)
        if(included IN_LIST MB_LAYER_PROGRAM_FOLDERS)
          set(why "${included}/ is a program (${MB_LAYER_TARGET_${included}}), not a library")
        else()
          set(why "${MB_LAYER_TARGET_${folder}} does not link ${MB_LAYER_TARGET_${included}}")
        endif()
        layer_error("${file}:${row}:${column}: error: ${folder}/ may not include ${included}/: ${why} "
                    "(a back edge? see docs/architecture.md \"Layers\")")
      endforeach()
    endforeach()
    if(NOT folder IN_LIST MB_LAYER_PROGRAM_FOLDERS)
      foreach(dep IN LISTS MB_LAYER_DEPS_${folder})
        if(NOT dep IN_LIST used)
          layer_error("CMakeLists.txt: error: ${MB_LAYER_TARGET_${folder}} links ${MB_LAYER_TARGET_${dep}}, "
                      "but no file of compiler/${folder}/ includes ${dep}/: drop the dependency")
        endif()
      endforeach()
    endif()
  endforeach()
endif()

if(DATA_DIR)
  set(folders ${MB_LAYER_FOLDERS} ${MB_LAYER_PROGRAM_FOLDERS})
  file(GLOB_RECURSE files ${DATA_DIR}/*.cpp ${DATA_DIR}/*.hpp)
  list(SORT files)
  foreach(file IN LISTS files)
    folder_includes(${file} content includes)
    foreach(line IN LISTS includes)
      included_folder("${line}" included)
      # The library's own folders (common/, models/, a slot's) are not layers; core/ is allowed.
      if(NOT included IN_LIST folders OR included STREQUAL "core")
        continue()
      endif()
      include_location("${content}" "${line}" row column)
      layer_error("${file}:${row}:${column}: error: the brick library may not include ${included}/: only core/ "
                  "lies below it (a back edge? see docs/architecture.md \"Layers\")")
    endforeach()
  endforeach()
endif()

if(DOC)
  mb_layer_mermaid(graph)
  set(begin "<!-- layer graph: generated by cmake/CheckLayers.cmake (cmake --build build --target mb_layer_graph) -->\n")
  set(end "<!-- end of layer graph -->")
  file(READ ${DOC} doc)
  string(FIND "${doc}" "${begin}" at_begin)
  string(FIND "${doc}" "${end}" at_end)
  if(at_begin LESS 0 OR at_end LESS at_begin)
    layer_error("${DOC}:1:1: error: no layer graph section (the markers '${begin}' ... '${end}')")
  else()
    string(LENGTH "${begin}" length)
    math(EXPR from "${at_begin} + ${length}")
    math(EXPR length "${at_end} - ${from}")
    string(SUBSTRING "${doc}" ${from} ${length} current)
    if(NOT current STREQUAL graph)
      if(UPDATE_DOC)
        string(SUBSTRING "${doc}" 0 ${from} head)
        string(SUBSTRING "${doc}" ${at_end} -1 tail)
        file(WRITE ${DOC} "${head}${graph}${tail}")
        message(NOTICE "${DOC}: layer graph updated")
      else()
        string(SUBSTRING "${doc}" 0 ${at_begin} before)
        string(REGEX MATCHALL "\n" newlines "${before}")
        list(LENGTH newlines row)
        math(EXPR row "${row} + 2")
        layer_error("${DOC}:${row}:1: error: the layer graph is not the targets' graph: "
                    "cmake --build build --target mb_layer_graph rewrites it")
      endif()
    endif()
  endif()
endif()

if(errors GREATER 0)
  message(FATAL_ERROR "${errors} layer error(s)")
endif()
if(STAMP)
  file(TOUCH ${STAMP})
endif()
