# The unity check: the sanitizer and fuzz trees compile unity sources (16 .cpp files of a target in one compile, all
# in one anonymous namespace), the Release tree compiles file by file. A file-local name that two files of one unity
# source define ("redefinition", "ambiguous") would break only those trees, which are built late (scripts/test) or
# not at all (a developer's Release build). shadowlab_unity_check() gives a tree that is not unity the target
# `unity_check`: the same unity sources, checked with -fsyntax-only.
#
# The grouping is CMake's own: each target gets a copy (an OBJECT library unity_check_<target>) with UNITY_BUILD on,
# the same batch size, and the same sources in the same order less those CMake would leave out of a unity source
# (SKIP_UNITY_BUILD_INCLUSION or a per-file COMPILE_OPTIONS / COMPILE_DEFINITIONS / COMPILE_FLAGS /
# INCLUDE_DIRECTORIES, read in the target's own folder); they are compiled on their own in those trees as here.
# The copy links what the target links (same include folders and definitions). scripts/unity-syntax-check is its
# compiler launcher: it runs the compile with -fsyntax-only, skips unity sources of one file and, on an error, names
# the files of the unity source the error and its notes point at. The build tool's depfiles keep it incremental.

# The buildsystem targets of `dir` and every folder below it.
function(_shadowlab_unity_check_targets dir out)
  get_property(targets DIRECTORY ${dir} PROPERTY BUILDSYSTEM_TARGETS)
  get_property(subdirs DIRECTORY ${dir} PROPERTY SUBDIRECTORIES)
  foreach(sub ${subdirs})
    _shadowlab_unity_check_targets(${sub} below)
    list(APPEND targets ${below})
  endforeach()
  set(${out} ${targets} PARENT_SCOPE)
endfunction()

# shadowlab_unity_check(ROOT <folder paths are shown relative to>): call at the end of the top-level CMakeLists.txt,
# after every target exists. Targets whose UNITY_BUILD property is set false are compiled file by file in every
# tree, so they are left out.
function(shadowlab_unity_check)
  cmake_parse_arguments(ARG "" "ROOT" "" ${ARGN})
  set(launcher ${Python3_EXECUTABLE} ${CMAKE_CURRENT_FUNCTION_LIST_DIR}/../scripts/unity-syntax-check --root ${ARG_ROOT})
  _shadowlab_unity_check_targets(${CMAKE_CURRENT_SOURCE_DIR} targets)
  add_custom_target(unity_check ALL)
  foreach(target ${targets})
    get_target_property(type ${target} TYPE)
    get_target_property(unity ${target} UNITY_BUILD)
    if(NOT type MATCHES "^(EXECUTABLE|STATIC_LIBRARY|SHARED_LIBRARY|MODULE_LIBRARY|OBJECT_LIBRARY)$"
       OR (NOT unity MATCHES "NOTFOUND$" AND NOT unity))
      continue()
    endif()
    get_target_property(source_dir ${target} SOURCE_DIR)
    get_target_property(sources ${target} SOURCES)
    set(kept)
    set(generated OFF)
    foreach(source ${sources})
      if(source MATCHES "\\$<")
        continue()  # objects of other targets
      endif()
      if(NOT IS_ABSOLUTE ${source})
        set(source ${source_dir}/${source})
      endif()
      # A generated source or header is made by a rule of the target's own folder: then the target comes first.
      get_source_file_property(made ${source} DIRECTORY ${source_dir} GENERATED)
      if(made)
        set(generated ON)
      endif()
      if(NOT source MATCHES "\\.(c|cc|cpp|cxx)$")
        continue()  # a header: never in a unity source
      endif()
      set(alone OFF)
      foreach(property SKIP_UNITY_BUILD_INCLUSION HEADER_FILE_ONLY)
        get_source_file_property(value ${source} DIRECTORY ${source_dir} ${property})
        if(value)
          set(alone ON)
        endif()
      endforeach()
      foreach(property COMPILE_OPTIONS COMPILE_DEFINITIONS COMPILE_FLAGS INCLUDE_DIRECTORIES)
        get_source_file_property(value ${source} DIRECTORY ${source_dir} ${property})
        if(NOT value STREQUAL "NOTFOUND" AND NOT value STREQUAL "")
          set(alone ON)
        endif()
      endforeach()
      if(NOT alone)
        list(APPEND kept ${source})
      endif()
    endforeach()
    list(LENGTH kept count)
    if(count LESS 2)
      continue()
    endif()
    set(copy unity_check_${target})
    add_library(${copy} OBJECT EXCLUDE_FROM_ALL ${kept})
    # The target's own compile settings with those its libraries pass on (the generator expression evaluates them on
    # the target, in its folder, where libraries found there, e.g. GTest, are visible).
    foreach(property INCLUDE_DIRECTORIES COMPILE_DEFINITIONS COMPILE_OPTIONS COMPILE_FEATURES)
      set_property(TARGET ${copy} PROPERTY ${property} "$<TARGET_PROPERTY:${target},${property}>")
    endforeach()
    foreach(property C_STANDARD CXX_STANDARD CXX_EXTENSIONS POSITION_INDEPENDENT_CODE UNITY_BUILD_BATCH_SIZE
             UNITY_BUILD_MODE UNITY_BUILD_CODE_BEFORE_INCLUDE UNITY_BUILD_CODE_AFTER_INCLUDE UNITY_BUILD_UNIQUE_ID)
      get_target_property(value ${target} ${property})
      if(NOT value STREQUAL "value-NOTFOUND")
        set_property(TARGET ${copy} PROPERTY ${property} "${value}")
      endif()
    endforeach()
    set_target_properties(${copy} PROPERTIES UNITY_BUILD ON
      C_COMPILER_LAUNCHER "${launcher};--target;${target}" CXX_COMPILER_LAUNCHER "${launcher};--target;${target}")
    # Built after the project's libraries the target links (their generated headers), not after the target itself
    # (a test target is not linked for its check) unless it has generated files of its own.
    get_target_property(links ${target} LINK_LIBRARIES)
    foreach(link ${links})
      if(TARGET ${link})
        get_target_property(imported ${link} IMPORTED)
        if(NOT imported)
          add_dependencies(${copy} ${link})
        endif()
      endif()
    endforeach()
    if(generated)
      add_dependencies(${copy} ${target})
    endif()
    add_dependencies(unity_check ${copy})
  endforeach()
endfunction()
