# ctest driver (cmake -P) for a build with CONFVIS_SHARED_LIBS=ON: the shared libraries export
# the public API and nothing else, and the binaries link what they should.
# - Every confvis symbol that a library in LIBRARIES exports (nm -D) is named in a public header
#   (SOURCE_DIR's */include/**.hpp, and the two src/ headers that the runtime uses from the
#   Vulkan backend and opens with CONFVIS_API: the headers that say CONFVIS_API); its innermost
#   name (function, class, member) must be a word of those headers. A library built without
#   hidden visibility would export its internals (functions of src/*.cpp, anonymous helpers'
#   callers, internal classes) and fail here.
# - Each library has internals that this check would catch were they exported (nm without -D
#   finds them in its symbol table), so the check above is not vacuous.
# - TEST_BINARY (confvis_tests) links the modules' objects, no libconfvis_*.so (it reaches into
#   internals, and a module both linked from objects and loaded as a library would exist twice);
#   CLI (confvis) links the libraries.
# Arguments: -DLIBRARIES=<paths;...> -DSOURCE_DIR= -DNM= -DREADELF= -DTEST_BINARY= -DCLI=
cmake_minimum_required(VERSION 3.25)  # list() policies for a script
include(${CMAKE_CURRENT_LIST_DIR}/cmake/driver_support.cmake)
require_driver_arguments(check_shared_exports.cmake LIBRARIES SOURCE_DIR NM READELF TEST_BINARY
                         CLI)

# The words of the headers that declare exported API.
file(GLOB_RECURSE headers RELATIVE ${SOURCE_DIR} ${SOURCE_DIR}/*.hpp)
list(FILTER headers INCLUDE REGEX "/(include/confvis|src)/")
list(FILTER headers EXCLUDE REGEX "^(build|tests/|tools/)")
set(public_words "")
set(public_headers 0)
foreach(header IN LISTS headers)
  file(READ ${SOURCE_DIR}/${header} text)
  if(header MATCHES "/src/" AND NOT text MATCHES "namespace confvis CONFVIS_API")
    continue()  # an internal header
  endif()
  math(EXPR public_headers "${public_headers} + 1")
  string(REGEX MATCHALL "[A-Za-z_][A-Za-z0-9_]*" words "${text}")
  list(APPEND public_words ${words})
  list(REMOVE_DUPLICATES public_words)
endforeach()
if(public_headers LESS 20)
  message(FATAL_ERROR "only ${public_headers} public headers under ${SOURCE_DIR}")
endif()

# innermost_name(SYMBOL OUT): the demangled symbol's innermost name ("confvis::vulkan::
# VulkanContext::~VulkanContext(...)" -> VulkanContext); empty for an operator, or for a symbol
# outside confvis (template instances of std, ...).
function(innermost_name symbol out)
  set(${out} "" PARENT_SCOPE)
  string(REGEX REPLACE "^(vtable|typeinfo|typeinfo name|VTT|guard variable|construction vtable) for "
         "" name "${symbol}")
  if(NOT name MATCHES "^confvis::")
    return()
  endif()
  string(REGEX REPLACE "{abi:[^}]*}" "" name "${name}")  # the ABI tags ([abi:cxx11])
  string(REPLACE "(anonymous namespace)::" "" name "${name}")  # before the parameters go
  string(REGEX REPLACE "\\(.*$" "" name "${name}")      # the parameters, and what follows
  set(previous "")
  while(NOT name STREQUAL previous)                      # template arguments, innermost first
    set(previous "${name}")
    string(REGEX REPLACE "<[^<>]*>" "" name "${name}")
  endwhile()
  string(REGEX REPLACE "^.*::" "" name "${name}")
  string(REGEX REPLACE "^~" "" name "${name}")
  if(name MATCHES "^operator" OR name STREQUAL "")
    return()
  endif()
  set(${out} "${name}" PARENT_SCOPE)
endfunction()

# symbols(LIBRARY DYNAMIC OUT): the defined symbols, demangled, one list entry each.
function(symbols library dynamic out)
  set(flags -C --defined-only)
  if(dynamic)
    list(PREPEND flags -D)
  endif()
  execute_process(COMMAND ${NM} ${flags} ${library} RESULT_VARIABLE rc OUTPUT_VARIABLE listing
                  ERROR_VARIABLE errors)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${NM} ${flags} ${library} failed: ${errors}")
  endif()
  string(REPLACE ";" "," listing "${listing}")          # no list separators inside a name,
  string(REPLACE "[" "{" listing "${listing}")          # no brackets (which hold a list together)
  string(REPLACE "]" "}" listing "${listing}")
  string(REGEX REPLACE "\n[0-9a-fA-F]* [A-Za-z] " "\n" listing "\n${listing}")
  string(REPLACE "\n" ";" listing "${listing}")
  list(FILTER listing INCLUDE REGEX "confvis::")
  set(${out} "${listing}" PARENT_SCOPE)
endfunction()

set(failures "")
foreach(library IN LISTS LIBRARIES)
  get_filename_component(library_name ${library} NAME)
  symbols(${library} ON exported)
  set(public 0)
  foreach(symbol IN LISTS exported)
    # The RTTI of a lambda inside a member of an exported class (GCC gives the closure type the
    # class's visibility, e.g. std::function targets in EmbreeBackend::Impl): a closure type
    # cannot be named outside its function, so this exposes no API.
    if(symbol MATCHES "^typeinfo (name )?for .*::\\{lambda\\(")
      continue()
    endif()
    innermost_name("${symbol}" name)
    if(name STREQUAL "")
      continue()
    endif()
    list(FIND public_words "${name}" at)
    if(at EQUAL -1)
      string(APPEND failures "  ${library_name} exports ${symbol}\n")
    else()
      math(EXPR public "${public} + 1")
    endif()
  endforeach()
  if(public EQUAL 0)
    string(APPEND failures "  ${library_name} exports no public confvis symbol\n")
  endif()
  # Internals present but hidden: a name that no public header has.
  symbols(${library} OFF all)
  set(hidden "")
  foreach(symbol IN LISTS all)
    innermost_name("${symbol}" name)
    if(NOT name STREQUAL "")
      list(FIND public_words "${name}" at)
      if(at EQUAL -1)
        set(hidden "${symbol}")
        break()
      endif()
    endif()
  endforeach()
  if(hidden STREQUAL "")
    string(APPEND failures "  ${library_name} has no internal symbol in its symbol table "
                           "(stripped? then this check proves nothing)\n")
  endif()
  message(STATUS "${library_name}: ${public} public symbols exported; internals hidden "
                 "(such as ${hidden})")
endforeach()

# needed(BINARY OUT): the shared libraries BINARY needs (readelf -d).
function(needed binary out)
  run("reading the dynamic section of ${binary}" ${READELF} -d ${binary})
  string(REGEX MATCHALL "Shared library: \\[[^]]*\\]" entries "${output}")
  set(${out} "${entries}" PARENT_SCOPE)
endfunction()
needed(${TEST_BINARY} test_needs)
if(test_needs MATCHES "libconfvis_")
  string(APPEND failures "  ${TEST_BINARY} loads confvis libraries (it links the modules' objects): "
                         "${test_needs}\n")
endif()
needed(${CLI} cli_needs)
if(NOT cli_needs MATCHES "libconfvis_runtime")
  string(APPEND failures "  ${CLI} does not link libconfvis_runtime.so: ${cli_needs}\n")
endif()
if(failures)
  message(FATAL_ERROR "shared libraries:\n${failures}")
endif()
