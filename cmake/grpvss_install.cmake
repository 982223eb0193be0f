# `cmake --install build [--prefix DIR]`: the stage libraries, the public headers, the CLI and a
# CMake package, so that another project writes
#   find_package(grpvss REQUIRED)
#   target_link_libraries(app PRIVATE grpvss::grpvss)
# (docs/install.md; tests/install/ builds such a project against an installed tree).
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(GRPVSS_CMAKE_INSTALL_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/grpvss)
get_property(GRPVSS_INSTALLED_STAGES GLOBAL PROPERTY GRPVSS_STAGES)
install(TARGETS ${GRPVSS_INSTALLED_STAGES} grpvss_all
        EXPORT grpvssTargets
        ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
        INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${CMAKE_SOURCE_DIR}/include/grpvss DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(TARGETS grpvss RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
install(EXPORT grpvssTargets NAMESPACE grpvss:: DESTINATION ${GRPVSS_CMAKE_INSTALL_DIR})
configure_package_config_file(${CMAKE_SOURCE_DIR}/cmake/grpvssConfig.cmake.in
                              ${CMAKE_BINARY_DIR}/grpvssConfig.cmake
                              INSTALL_DESTINATION ${GRPVSS_CMAKE_INSTALL_DIR})
write_basic_package_version_file(${CMAKE_BINARY_DIR}/grpvssConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${CMAKE_BINARY_DIR}/grpvssConfig.cmake ${CMAKE_BINARY_DIR}/grpvssConfigVersion.cmake
        DESTINATION ${GRPVSS_CMAKE_INSTALL_DIR})
