# Sanitizers and libFuzzer coverage for every raylab target (tests/fuzz/README.md says how CI uses
# them). Included before the first target so add_compile_options reaches all of them.
set(RAYLAB_SANITIZE "" CACHE STRING "Sanitizers for every target, as -fsanitize takes them (e.g. address,undefined); empty: none")
option(RAYLAB_FUZZ "Build the libFuzzer harnesses of tests/fuzz (clang only; needs RAYLAB_SANITIZE with address)" OFF)

if(RAYLAB_SANITIZE)
  add_compile_options(-fsanitize=${RAYLAB_SANITIZE} -fno-omit-frame-pointer -fno-sanitize-recover=all)
  add_link_options(-fsanitize=${RAYLAB_SANITIZE})
endif()

if(RAYLAB_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang" OR NOT CMAKE_C_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "RAYLAB_FUZZ=ON needs clang for C and C++ (libFuzzer is part of clang), got "
                        "${CMAKE_C_COMPILER_ID} and ${CMAKE_CXX_COMPILER_ID}: configure with "
                        "-DCMAKE_C_COMPILER=clang-16 -DCMAKE_CXX_COMPILER=clang++-16")
  endif()
  # The shaders compiled as C++ (shaders/include/compat.glsl) construct structs with parentheses,
  # which clang implements from version 16.
  if(CMAKE_CXX_COMPILER_VERSION VERSION_LESS 16)
    message(FATAL_ERROR "RAYLAB_FUZZ=ON needs clang 16 or newer (Debian 12: clang-16), got "
                        "${CMAKE_CXX_COMPILER_VERSION}: configure with -DCMAKE_CXX_COMPILER=clang++-16")
  endif()
  if(NOT RAYLAB_SANITIZE MATCHES "(^|,)address(,|$)")
    message(FATAL_ERROR "RAYLAB_FUZZ=ON needs AddressSanitizer: add -DRAYLAB_SANITIZE=address,undefined")
  endif()
  # Coverage instrumentation without libFuzzer's main(), so the same objects also link the tests;
  # the harnesses in tests/fuzz link -fsanitize=fuzzer themselves.
  add_compile_options(-fsanitize=fuzzer-no-link)
endif()
