# Warnings and engine-wide compile rules, applied through one interface target.
add_library(starbow_options INTERFACE)
target_compile_options(starbow_options INTERFACE
  -Wall -Wextra -Wshadow=local -Wno-missing-field-initializers
  $<$<COMPILE_LANGUAGE:CXX>:-fno-exceptions -fno-rtti>)
if(STARBOW_SANITIZE)
  target_compile_options(starbow_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                         -fno-sanitize-recover=undefined)
  target_link_options(starbow_options INTERFACE -fsanitize=address,undefined)
endif()

# Tests and tools may use exceptions (GoogleTest does); they get a separate option set.
add_library(starbow_test_options INTERFACE)
target_compile_options(starbow_test_options INTERFACE -Wall -Wextra -Wno-missing-field-initializers)
if(STARBOW_SANITIZE)
  target_compile_options(starbow_test_options INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer
                         -fno-sanitize-recover=undefined)
  target_link_options(starbow_test_options INTERFACE -fsanitize=address,undefined)
endif()

# starbow_module(name DIR dir DEPS ...): a static library from every .cpp in dir.
function(starbow_module name)
  cmake_parse_arguments(M "" "DIR" "DEPS" ${ARGN})
  file(GLOB srcs CONFIGURE_DEPENDS "${M_DIR}/*.cpp")
  if(srcs)
    add_library(${name} STATIC ${srcs})
    target_include_directories(${name} PUBLIC ${CMAKE_SOURCE_DIR})
    target_link_libraries(${name} PUBLIC starbow_options ${M_DEPS})
  else()  # a module with headers only (so far)
    add_library(${name} INTERFACE)
    target_include_directories(${name} INTERFACE ${CMAKE_SOURCE_DIR})
    target_link_libraries(${name} INTERFACE starbow_options ${M_DEPS})
  endif()
endfunction()
