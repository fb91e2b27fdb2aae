# The layer graph as data, shared by the configure step (cmake/Layers.cmake) and the include
# checker (cmake/CheckLayers.cmake, run with cmake -P). The graph is held in variables:
#   MB_LAYER_FOLDERS          the folders of compiler/ that are targets, in declaration order
#   MB_LAYER_TARGET_<folder>  the folder's CMake target
#   MB_LAYER_DEPS_<folder>    the folders whose targets it links directly
# A folder may include only its own files and those of the folders it links directly, like
# GN's `gn check` (a transitive dependency is not enough: the graph says what each folder uses).

# Sets `out` to a cycle "a -> b -> ... -> a" of the graph, or to "" when it is acyclic.
function(mb_layer_cycle out)
  foreach(folder IN LISTS MB_LAYER_FOLDERS)
    set(state_${folder} "")
  endforeach()
  # Iterative depth-first search: a folder is "open" while its dependencies are being walked;
  # meeting an open folder again closes a cycle.
  foreach(root IN LISTS MB_LAYER_FOLDERS)
    if(state_${root})
      continue()
    endif()
    set(stack ${root})
    set(path ${root})
    set(state_${root} open)
    set(next_${root} 0)
    while(stack)
      list(GET stack -1 top)
      list(LENGTH MB_LAYER_DEPS_${top} count)
      if(next_${top} LESS count)
        list(GET MB_LAYER_DEPS_${top} ${next_${top}} dep)
        math(EXPR next_${top} "${next_${top}} + 1")
        if(state_${dep} STREQUAL "open")
          list(FIND path ${dep} at)
          list(SUBLIST path ${at} -1 cycle)
          list(APPEND cycle ${dep})
          list(JOIN cycle " -> " text)
          set(${out} "${text}" PARENT_SCOPE)
          return()
        elseif(NOT state_${dep})
          set(state_${dep} open)
          set(next_${dep} 0)
          list(APPEND stack ${dep})
          list(APPEND path ${dep})
        endif()
      else()
        set(state_${top} done)
        list(POP_BACK stack)
        list(POP_BACK path)
      endif()
    endwhile()
  endforeach()
  set(${out} "" PARENT_SCOPE)
endfunction()

# Sets `out` to the graph as a Mermaid flowchart (docs/architecture.md "Layers"): one node per
# folder, named by its target, and an arrow from each folder to each folder it links directly.
function(mb_layer_mermaid out)
  set(text "```mermaid\nflowchart BT\n")
  foreach(folder IN LISTS MB_LAYER_FOLDERS)
    string(APPEND text "  ${folder}[\"${folder}/ (${MB_LAYER_TARGET_${folder}})\"]\n")
  endforeach()
  foreach(folder IN LISTS MB_LAYER_FOLDERS)
    foreach(dep IN LISTS MB_LAYER_DEPS_${folder})
      string(APPEND text "  ${folder} --> ${dep}\n")
    endforeach()
  endforeach()
  string(APPEND text "```\n")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()
