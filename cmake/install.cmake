# Installation: `cmake --install BUILD --prefix P` puts
#   lib/libcontactfx{,_files,_scene,_render}.a the core (files: whole-file writing for the components)
#                                               and the two optional components
#   include/contactfx/...                       public headers, version.h included
#   lib/cmake/contactfx/contactfxConfig*.cmake  find_package(contactfx [COMPONENTS scene render])
#   lib/pkgconfig/contactfx{,-scene,-render}.pc pkg-config
#   bin/contactfx, bin/contactfx-testbed        the programs (when built)
#   share/contactfx/scenes/                     bundled scenes and effects configs
include(CMakePackageConfigHelpers)

install(DIRECTORY ${PROJECT_SOURCE_DIR}/include/contactfx DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
  COMPONENT development FILES_MATCHING PATTERN "*.h")
install(FILES ${PROJECT_BINARY_DIR}/include/contactfx/version.h
  DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/contactfx COMPONENT development)

# One export set per component, so that a consumer of the core needs neither nlohmann-json nor Cairo.
install(TARGETS contactfx contactfx_files EXPORT contactfxTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  COMPONENT development)
install(TARGETS contactfx_scene EXPORT contactfxSceneTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  COMPONENT development)
install(TARGETS contactfx_render EXPORT contactfxRenderTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  COMPONENT development)
foreach(set contactfxTargets contactfxSceneTargets contactfxRenderTargets)
  install(EXPORT ${set} NAMESPACE contactfx:: DESTINATION ${CONTACTFX_INSTALL_CMAKEDIR}
    COMPONENT development)
endforeach()

configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/contactfxConfig.cmake.in
  ${PROJECT_BINARY_DIR}/contactfxConfig.cmake INSTALL_DESTINATION ${CONTACTFX_INSTALL_CMAKEDIR}
  PATH_VARS CONTACTFX_INSTALL_SCENESDIR)
# 0.x: only the same minor version is compatible; from 1.0 on, the same major version.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/contactfxConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/contactfxConfig.cmake ${PROJECT_BINARY_DIR}/contactfxConfigVersion.cmake
  DESTINATION ${CONTACTFX_INSTALL_CMAKEDIR} COMPONENT development)

file(RELATIVE_PATH PC_PREFIX_FROM_PCDIR "/prefix/${CMAKE_INSTALL_LIBDIR}/pkgconfig" "/prefix")
string(REGEX REPLACE "/$" "" PC_PREFIX_FROM_PCDIR "${PC_PREFIX_FROM_PCDIR}")
foreach(pc contactfx contactfx-scene contactfx-render)
  configure_file(${PROJECT_SOURCE_DIR}/cmake/${pc}.pc.in ${PROJECT_BINARY_DIR}/pkgconfig/${pc}.pc @ONLY)
  install(FILES ${PROJECT_BINARY_DIR}/pkgconfig/${pc}.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig
    COMPONENT development)
endforeach()

if(TARGET contactfx_cli)
  install(TARGETS contactfx_cli contactfx_testbed OPTIONAL RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR}
    COMPONENT programs)
endif()
install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${CONTACTFX_INSTALL_SCENESDIR}
  COMPONENT programs FILES_MATCHING PATTERN "*.json")
