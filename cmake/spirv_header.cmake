# cmake -DSPIRV_OPT=PROGRAM -DIN=SHADER.spv -DARRAY=NAME -DHEADER=OUT.h -P spirv_header.cmake
# Optimises a shader's SPIR-V with spirv-opt and writes it as a C array of 32-bit words (what
# glslangValidator --vn writes), so that vkrt needs no shader files at run time.
#
# The passes make the driver's pipeline creation cheaper and leave the shader's arithmetic as
# it was (bench/README.md "Fixed cost of the Vulkan backend"): every function that can be
# inlined is, and the rest of the names and debug information go. No function with a return
# before its end is inlined (that needs merge-return, whose one-pass loop makes the code
# llvmpipe runs slower), and no folding or SSA pass runs (folding reassociates arithmetic:
# other images; SSA form before the driver's made slower code).
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
