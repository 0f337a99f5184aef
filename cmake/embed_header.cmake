# cmake -DIN=FILE -DARRAY=NAME -DHEADER=OUT.h [-DSPIRV_OPT=PROGRAM] -P embed_header.cmake
# Writes FILE into the header OUT.h as a C array, so that vkrt needs no data files at run time
# (CMakeLists.txt, vkrt_embed).
#
# With SPIRV_OPT, FILE is a shader's SPIR-V: optimised with spirv-opt and written as an array
# of 32-bit words (what glslangValidator --vn writes). The passes make the driver's pipeline
# creation cheaper and leave the shader's arithmetic as it was (bench/README.md "Fixed cost of
# the Vulkan backend"): every function that can be inlined is, and the rest of the names and
# debug information go. No function with a return before its end is inlined (that needs
# merge-return, whose one-pass loop makes the code llvmpipe runs slower), and no folding or
# SSA pass runs (folding reassociates arithmetic: other images; SSA form before the driver's
# made slower code).
#
# Without it, FILE's bytes as they are (the grading report's style sheet and script):
# `unsigned char NAME[]`, ended by a 0 that is not counted, and `NAMESize`, their count.
if(DEFINED SPIRV_OPT)
  execute_process(
    COMMAND ${SPIRV_OPT} --target-env=vulkan1.1 --inline-entry-points-exhaustive --eliminate-dead-functions
            --strip-debug ${IN} -o ${IN}.opt
    RESULT_VARIABLE result
    OUTPUT_VARIABLE messages   # a warning per function left as it is: printed only on failure
    ERROR_VARIABLE messages)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "spirv-opt ${IN} failed:\n${messages}")
  endif()
  file(READ ${IN}.opt hex HEX)
  # Little-endian bytes -> words, eight to a line.
  string(REGEX REPLACE "(..)(..)(..)(..)" "0x\\4\\3\\2\\1," words "${hex}")
  string(REPEAT "0x........," 8 line)
  string(REGEX REPLACE "(${line})" "\\1\n" words "${words}")
  file(WRITE ${HEADER} "#pragma once\nconst uint32_t ${ARRAY}[] = {\n${words}\n};\n")
else()
  file(READ ${IN} hex HEX)
  string(LENGTH "${hex}" digits)
  math(EXPR size "${digits} / 2")
  # Bytes, sixteen to a line.
  string(REGEX REPLACE "(..)" "0x\\1," bytes "${hex}")
  string(REPEAT "0x..," 16 line)
  string(REGEX REPLACE "(${line})" "\\1\n" bytes "${bytes}")
  file(WRITE ${HEADER} "#pragma once\n#include <cstddef>\n"
                       "inline constexpr unsigned char ${ARRAY}[] = {\n${bytes}0x00};\n"
                       "inline constexpr std::size_t ${ARRAY}Size = ${size};\n")
endif()
