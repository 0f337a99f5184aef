# `cmake --install` into a fresh prefix: vkrt in PREFIX/bin, the man page in
# PREFIX/share/man/man1, the page formats without warnings, and every option that
# `vkrt --help` lists is in it. Run by CTest:
#   cmake -DBUILD_DIR=... -DPREFIX=... -P tests/install_test.cmake
file(REMOVE_RECURSE "${PREFIX}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc}):\n${out}")
endif()
set(binary "${PREFIX}/bin/vkrt")
set(page_gz "${PREFIX}/share/man/man1/vkrt.1.gz")
set(completion "${PREFIX}/share/bash-completion/completions/vkrt")
foreach(f "${binary}" "${page_gz}" "${completion}")
  if(NOT EXISTS "${f}")
    message(FATAL_ERROR "not installed: ${f}\n${out}")
  endif()
endforeach()

# The page, compressed (gzip -n, as Debian's policy asks): decompressed here to check it.
set(page "${PREFIX}/vkrt.1")
execute_process(COMMAND gzip -d -c "${page_gz}" OUTPUT_FILE "${page}" RESULT_VARIABLE rc ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${page_gz} does not decompress (${rc}): ${err}")
endif()

# The installed binary runs.
execute_process(COMMAND "${binary}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE help ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  message(FATAL_ERROR "${binary} --help exited ${rc}: ${err}")
endif()

# The page formats: with groff, with warnings on (-ww) and every warning a failure; else
# with man -l; else a sanity check of its first macro.
find_program(GROFF groff)
find_program(MAN man)
if(GROFF)
  execute_process(COMMAND "${GROFF}" -man -Tutf8 -ww -z "${page}" RESULT_VARIABLE rc ERROR_VARIABLE err)
  if(NOT rc EQUAL 0 OR NOT err STREQUAL "")
    message(FATAL_ERROR "groff reports problems in ${page} (${rc}):\n${err}")
  endif()
elseif(MAN)
  execute_process(COMMAND "${MAN}" -l "${page}" RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "man -l ${page} failed (${rc}):\n${err}")
  endif()
else()
  file(STRINGS "${page}" th REGEX "^\\.TH VKRT 1 ")
  if(th STREQUAL "")
    message(FATAL_ERROR "${page} has no '.TH VKRT 1' line")
  endif()
  message(STATUS "neither groff nor man: only checked the .TH line")
endif()

# Consistency with --help: each option it lists (the first word of an indented line
# starting with '-') appears in the page, whose '\-' is read as '-'.
file(READ "${page}" text)
string(REPLACE "\\-" "-" text "${text}")
string(REGEX MATCHALL "\n  +-[-a-z]+" options "${help}")
list(LENGTH options count)
if(count LESS 20)
  message(FATAL_ERROR "found only ${count} options in --help:\n${help}")
endif()
foreach(o ${options})
  string(STRIP "${o}" o)
  string(FIND "${text}" "${o}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "option ${o} of --help is not in the man page ${page}")
  endif()
endforeach()
message(STATUS "installed and checked: ${binary}, ${page} (${count} options of --help in the page)")
