# `cmake --install`: the rotorsweep executable, the libraries as rotorsweep::kernels, ::ensemble,
# ::io and ::landscape with their headers, and rotorsweepConfig.cmake for find_package(rotorsweep).
include(CMakePackageConfigHelpers)

set(ROTORSWEEP_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/rotorsweep)
foreach(part kernels ensemble io landscape)
  set_target_properties(rotorsweep_${part} PROPERTIES EXPORT_NAME ${part})
  install(DIRECTORY ${PROJECT_SOURCE_DIR}/${part}/ DESTINATION ${ROTORSWEEP_INCLUDE_DIR}/${part}
          FILES_MATCHING PATTERN "*.hpp")
endforeach()
# A consumer compiles the header-only kernels: it needs the instruction set the libraries were
# built for (the SIMD lane width is part of their interface) and no floating-point contraction.
target_compile_options(rotorsweep_kernels INTERFACE
                       $<INSTALL_INTERFACE:-ffp-contract=off $<$<BOOL:${ROTORSWEEP_NATIVE}>:-march=native>>)

install(TARGETS rotorsweep_kernels rotorsweep_ensemble rotorsweep_io rotorsweep_landscape
        EXPORT rotorsweepTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
install(TARGETS rotorsweep RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT rotorsweepTargets NAMESPACE rotorsweep:: DESTINATION ${ROTORSWEEP_CMAKE_DIR})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/rotorsweepConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/rotorsweepConfig.cmake INSTALL_DESTINATION ${ROTORSWEEP_CMAKE_DIR})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/rotorsweepConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/rotorsweepConfig.cmake ${PROJECT_BINARY_DIR}/rotorsweepConfigVersion.cmake
        DESTINATION ${ROTORSWEEP_CMAKE_DIR})
