# Registers raylab_tests with ctest in groups that carry labels, so `ctest -L`/`-LE` picks a subset:
#   gl      the test file needs an OpenGL context (includes a header that reaches gl_test.h) or runs
#           raylab-render / raylab-bench;
#   window  the test file runs the viewer program under Xvfb;
#   cpu     neither of those;
#   slow    the test is marked with a `// ctest: slow` line right above its TEST line.
# A test has one label, its kind with `-slow` appended when marked (gtest_discover_tests flattens
# a list of labels); ctest's -L and -LE take regular expressions, so `-L gl` also selects gl-slow.
# `ctest -LE 'gl|window|slow'` is the quick subset. Tests the scan does not recognise are still
# registered, unlabelled, so none is ever dropped.

# Headers under `dir` that include gl_test.h directly or through another such header.
function(_raylab_gl_headers dir out)
  file(GLOB_RECURSE headers "${dir}/*.h")
  set(gl "gl_test.h")
  set(changed TRUE)
  while(changed)
    set(changed FALSE)
    foreach(h IN LISTS headers)
      get_filename_component(name "${h}" NAME)
      if(name IN_LIST gl)
        continue()
      endif()
      file(READ "${h}" text)
      foreach(g IN LISTS gl)
        string(REPLACE "." "\\." g_re "${g}")
        if(text MATCHES "#include \"[^\"]*${g_re}\"")
          list(APPEND gl "${name}")
          set(changed TRUE)
          break()
        endif()
      endforeach()
    endforeach()
  endwhile()
  set(${out} "${gl}" PARENT_SCOPE)
endfunction()

# raylab_discover_labelled_tests(TARGET SOURCES files... OPTIONS gtest_discover_tests options...
#                                PROPERTIES test properties...): gtest_discover_tests once per group.
function(raylab_discover_labelled_tests target)
  cmake_parse_arguments(ARG "" "" "SOURCES;OPTIONS;PROPERTIES" ${ARGN})
  # The labels are read from the sources: an edited test file re-runs the scan.
  set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${ARG_SOURCES})
  _raylab_gl_headers("${CMAKE_CURRENT_SOURCE_DIR}" gl_headers)
  set(groups "")
  set(all "")
  foreach(src IN LISTS ARG_SOURCES)
    file(READ "${src}" text)
    set(file_labels "cpu")
    if(text MATCHES "RAYLAB_VIEWER_EXE|viewer_run\\.h")
      set(file_labels "window")
    elseif(text MATCHES "RAYLAB_RENDER_EXE|RAYLAB_BENCH_EXE|createHeadlessContext")
      set(file_labels "gl")
    else()
      foreach(g IN LISTS gl_headers)
        string(REPLACE "." "\\." g_re "${g}")
        if(text MATCHES "#include \"[^\"]*${g_re}\"")
          set(file_labels "gl")
          break()
        endif()
      endforeach()
    endif()
    string(REGEX MATCHALL "(// ctest: slow[ \t]*\n[ \t]*)?TEST(_F|_P)?\\([ \t\r\n]*[A-Za-z0-9_]+,[ \t\r\n]*[A-Za-z0-9_]+"
           tests "${text}")
    foreach(t IN LISTS tests)
      set(labels "${file_labels}")
      if(t MATCHES "^// ctest: slow")
        list(APPEND labels slow)
      endif()
      string(REGEX REPLACE ".*TEST(_F|_P)?\\([ \t\r\n]*([A-Za-z0-9_]+),[ \t\r\n]*([A-Za-z0-9_]+)$" "\\2.\\3" name "${t}")
      if(t MATCHES "TEST_P\\(")
        set(name "*/${name}/*")
      endif()
      list(JOIN labels "-" group)
      if(NOT group IN_LIST groups)
        list(APPEND groups "${group}")
        set(patterns_${group} "")
      endif()
      list(APPEND patterns_${group} "${name}")
      list(APPEND all "${name}")
    endforeach()
  endforeach()
  foreach(group IN LISTS groups)
    list(JOIN patterns_${group} ":" filter)
    gtest_discover_tests(${target} TEST_FILTER "${filter}" ${ARG_OPTIONS} PROPERTIES LABELS "${group}" ${ARG_PROPERTIES})
  endforeach()
  list(JOIN all ":" every)
  gtest_discover_tests(${target} TEST_FILTER "-${every}" ${ARG_OPTIONS} PROPERTIES ${ARG_PROPERTIES})
endfunction()
