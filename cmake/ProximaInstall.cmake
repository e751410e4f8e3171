# `cmake --install` (Documentation/Library.md): the components' export sets, ProximaConfig.cmake
# with its version file, and a pkg-config file for the kernel. Included after every layer has
# registered its libraries (proxima_install_library), so that only the components this build has
# are exported.
include(CMakePackageConfigHelpers)

set(PROXIMA_CMAKE_DIR "${CMAKE_INSTALL_LIBDIR}/cmake/Proxima")
get_property(_components GLOBAL PROPERTY PROXIMA_INSTALLED_COMPONENTS)
list(REMOVE_DUPLICATES _components)
foreach(_component IN LISTS _components)
  install(EXPORT Proxima${_component}Targets NAMESPACE Proxima::
          DESTINATION "${PROXIMA_CMAKE_DIR}" COMPONENT ${_component})
endforeach()
set(PROXIMA_EXPORTED_COMPONENTS "${_components}")
# A scripted run couples a scene's bodies (IO/Scene/SceneBodies) when Dynamics is built.
if(PROXIMA_BUILD_DYNAMICS)
  set(PROXIMA_IO_NEEDS_DYNAMICS Dynamics)
else()
  set(PROXIMA_IO_NEEDS_DYNAMICS "")
endif()

configure_package_config_file(
  "${CMAKE_CURRENT_LIST_DIR}/Install/ProximaConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/ProximaConfig.cmake"
  INSTALL_DESTINATION "${PROXIMA_CMAKE_DIR}")
write_basic_package_version_file("${PROJECT_BINARY_DIR}/ProximaConfigVersion.cmake"
                                 COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/ProximaConfig.cmake"
              "${PROJECT_BINARY_DIR}/ProximaConfigVersion.cmake"
              "${CMAKE_CURRENT_LIST_DIR}/Install/ProximaInstalledModuleDir.cpp.in"
        DESTINATION "${PROXIMA_CMAKE_DIR}" COMPONENT Kernel)

# The licence and the credits of the shipped data go with every installation, where Debian keeps a
# package's (share/doc/proxima, not GNUInstallDirs' default share/doc/Proxima): a binary
# distribution must carry the BSD licence's text, and the meshes' CC BY terms ask for their
# credits. Kernel is the component every installation has.
install(FILES "${PROJECT_SOURCE_DIR}/LICENSE" "${PROJECT_SOURCE_DIR}/NOTICE"
        DESTINATION "${CMAKE_INSTALL_DOCDIR}" COMPONENT Kernel)

# The kernel for builds without CMake: plain C++20 and threads, no third-party package.
configure_file("${CMAKE_CURRENT_LIST_DIR}/Install/proxima-kernel.pc.in"
               "${PROJECT_BINARY_DIR}/proxima-kernel.pc" @ONLY)
install(FILES "${PROJECT_BINARY_DIR}/proxima-kernel.pc"
        DESTINATION "${CMAKE_INSTALL_LIBDIR}/pkgconfig" COMPONENT Kernel)
