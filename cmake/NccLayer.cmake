# ncc_layer(NAME SOURCES...): a layer library with public headers in include/.
# While a layer is being built up in parallel it may have no sources yet; it is then an
# INTERFACE library so the rest of the tree still configures. (Transitional: every layer
# has sources once the foundation lands.)
function(ncc_layer name)
  if(ARGN)
    add_library(${name} ${ARGN})
    target_include_directories(${name} PUBLIC include)
    set(NCC_LAYER_SCOPE PUBLIC PARENT_SCOPE)
  else()
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE include)
    set(NCC_LAYER_SCOPE INTERFACE PARENT_SCOPE)
  endif()
endfunction()
