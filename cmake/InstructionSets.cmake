# The instruction sets the SIMD kernels are compiled for. Portable builds (the default on x86-64)
# make one rotorsweep-<isa> per set and a launcher that runs the widest one the CPU can execute.
set(ROTORSWEEP_KNOWN_ISAS sse2 avx2 avx512)
if(CMAKE_SYSTEM_PROCESSOR MATCHES "^(x86_64|AMD64|amd64)$")
  set(default_isas "sse2;avx2;avx512")
else()
  set(default_isas native)
endif()
set(ROTORSWEEP_ISAS "${default_isas}" CACHE STRING
    "Instruction sets to build the kernels for: any of sse2;avx2;avx512 (one binary each, picked at run time), or native (one -march=native binary)")

# -march of each set: the x86-64 levels (v1 has SSE2, v3 adds AVX2 and FMA, v4 adds AVX-512 F/BW/CD/DQ/VL).
function(rotorsweep_isa_flags isa out)
  if(isa STREQUAL "sse2")
    set(${out} -march=x86-64 PARENT_SCOPE)
  elseif(isa STREQUAL "avx2")
    set(${out} -march=x86-64-v3 PARENT_SCOPE)
  elseif(isa STREQUAL "avx512")
    set(${out} -march=x86-64-v4 PARENT_SCOPE)
  elseif(isa STREQUAL "native")
    set(${out} -march=native PARENT_SCOPE)
  else()
    message(FATAL_ERROR "ROTORSWEEP_ISAS: unknown instruction set '${isa}'; allowed: sse2, avx2, avx512, or native alone")
  endif()
endfunction()

list(LENGTH ROTORSWEEP_ISAS isa_count)
if(isa_count EQUAL 0)
  message(FATAL_ERROR "ROTORSWEEP_ISAS is empty; allowed: any of sse2;avx2;avx512, or native")
endif()
if("native" IN_LIST ROTORSWEEP_ISAS)
  if(NOT isa_count EQUAL 1)
    message(FATAL_ERROR "ROTORSWEEP_ISAS: native builds one binary and cannot be combined with '${ROTORSWEEP_ISAS}'")
  endif()
  set(ROTORSWEEP_PORTABLE OFF)
else()
  set(ROTORSWEEP_PORTABLE ON)
endif()
foreach(isa ${ROTORSWEEP_ISAS})
  rotorsweep_isa_flags(${isa} unused)  # rejects unknown names at configure time
endforeach()

# The primary set: what the tests, the Python module and the installed libraries are built for,
# the widest listed set this (building) machine can run.
set(ROTORSWEEP_PRIMARY_ISA native)
if(ROTORSWEEP_PORTABLE)
  try_run(host_isa_run host_isa_compiled ${PROJECT_BINARY_DIR}/host_isa
          SOURCES ${PROJECT_SOURCE_DIR}/apps/launcher/host_isa_probe.cpp
          CMAKE_FLAGS -DINCLUDE_DIRECTORIES=${PROJECT_SOURCE_DIR}
          CXX_STANDARD 20
          RUN_OUTPUT_VARIABLE host_isas)
  string(STRIP "${host_isas}" host_isas)
  set(ROTORSWEEP_HOST_ISAS ${host_isas})
  set(ROTORSWEEP_PRIMARY_ISA "")
  foreach(isa ${ROTORSWEEP_KNOWN_ISAS})  # narrowest first
    if(isa IN_LIST host_isas AND isa IN_LIST ROTORSWEEP_ISAS)
      set(ROTORSWEEP_PRIMARY_ISA ${isa})
    endif()
  endforeach()
  if(NOT ROTORSWEEP_PRIMARY_ISA)
    list(GET ROTORSWEEP_ISAS 0 ROTORSWEEP_PRIMARY_ISA)
    message(WARNING "this machine runs none of ROTORSWEEP_ISAS (${ROTORSWEEP_ISAS}); the tests will not run here")
  endif()
endif()
rotorsweep_isa_flags(${ROTORSWEEP_PRIMARY_ISA} ROTORSWEEP_PRIMARY_FLAGS)
message(STATUS "instruction sets: ${ROTORSWEEP_ISAS} (primary: ${ROTORSWEEP_PRIMARY_ISA})")
