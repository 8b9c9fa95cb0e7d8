# `cmake --install`: the rotorsweep command (launcher and per-instruction-set binaries), the libraries
# as rotorsweep::kernels, ::ensemble, ::io and ::landscape with headers, and rotorsweepConfig.cmake.
include(CMakePackageConfigHelpers)

set(ROTORSWEEP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rotorsweep)
foreach(part kernels ensemble io landscape)
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${part}/ DESTINATION ${ROTORSWEEP_INCLUDE_DIR}/${part}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
foreach(part kernels io landscape ensemble_core gpu)
  set_target_properties(rotorsweep_${part} PROPERTIES EXPORT_NAME ${part})
endforeach()
# the libraries carry the sweeps of the primary instruction set (the widest this machine runs)
set_target_properties(rotorsweep_ensemble_${ROTORSWEEP_PRIMARY_ISA} PROPERTIES EXPORT_NAME ensemble)
# a consumer that links io alone gets the sweeps too, as before they were built per instruction set
target_link_libraries(rotorsweep_io INTERFACE $<INSTALL_INTERFACE:rotorsweep::ensemble>)
# A consumer compiles the header-only kernels: it needs the instruction set the libraries were
# built for (the SIMD lane width is part of their interface) and no floating-point contraction.
target_compile_options(rotorsweep_kernels INTERFACE $<INSTALL_INTERFACE:-ffp-contract=off ${ROTORSWEEP_PRIMARY_FLAGS}>)

install(TARGETS rotorsweep_kernels rotorsweep_gpu rotorsweep_ensemble_core rotorsweep_ensemble_${ROTORSWEEP_PRIMARY_ISA} rotorsweep_io
                rotorsweep_landscape EXPORT rotorsweepTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# the launcher and one binary per instruction set, side by side (the launcher looks beside itself)
install(TARGETS ${ROTORSWEEP_COMMAND_TARGETS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT rotorsweepTargets NAMESPACE rotorsweep:: DESTINATION ${ROTORSWEEP_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rotorsweepConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rotorsweepConfig.cmake INSTALL_DESTINATION ${ROTORSWEEP_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rotorsweepConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rotorsweepConfig.cmake ${PROJECT_BINARY_DIR}/rotorsweepConfigVersion.cmake
        DESTINATION ${ROTORSWEEP_CMAKE_DIR})
