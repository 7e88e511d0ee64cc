# Build ilahrs as a library for those who prefer linking to copying ilahrs.h and ilahrs.c:
#   cmake -S generated/c -B build/ilahrs && cmake --build build/ilahrs && cmake --install build/ilahrs
# Then link with `find_package(ilahrs 1.0)` (target ilahrs::ilahrs; any 1.x at or above the version asked for) or `pkg-config --cflags --libs ilahrs`.

include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

option(ILAHRS_BUILD_EXAMPLES "Build examples/decode_capture (needs ILAHRS_NAMES)" OFF)
option(ILAHRS_NAMES "Name strings, name accessors and by-name lookups (OFF: -DILAHRS_NAMES=0, see ilahrs.h)" ON)

add_library(ilahrs ilahrs.c)
add_library(ilahrs::ilahrs ALIAS ilahrs)
target_include_directories(ilahrs PUBLIC
    $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}>
    $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
set_target_properties(ilahrs PROPERTIES
    C_STANDARD 99
    C_STANDARD_REQUIRED ON
    C_EXTENSIONS OFF
    VERSION ${PROJECT_VERSION}
    PUBLIC_HEADER ilahrs.h)
# The header and the library must agree, so the definition is public (and in ilahrs.pc).
set(ILAHRS_PC_CFLAGS "")
if(NOT ILAHRS_NAMES)
    target_compile_definitions(ilahrs PUBLIC ILAHRS_NAMES=0)
    set(ILAHRS_PC_CFLAGS " -DILAHRS_NAMES=0")
endif()

if(ILAHRS_BUILD_EXAMPLES AND ILAHRS_NAMES)
    add_executable(decode_capture examples/decode_capture.c)
    target_link_libraries(decode_capture PRIVATE ilahrs::ilahrs)
endif()

install(TARGETS ilahrs EXPORT ilahrsTargets
    ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
    LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR}
    PUBLIC_HEADER DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(EXPORT ilahrsTargets NAMESPACE ilahrs:: FILE ilahrsConfig.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ilahrs)
# find_package(ilahrs 1.0) accepts this package for any 1.x at or above the version asked for.
write_basic_package_version_file(${CMAKE_CURRENT_BINARY_DIR}/ilahrsConfigVersion.cmake
    COMPATIBILITY SameMajorVersion)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ilahrsConfigVersion.cmake
    DESTINATION ${CMAKE_INSTALL_LIBDIR}/cmake/ilahrs)

configure_file(ilahrs.pc.in ${CMAKE_CURRENT_BINARY_DIR}/ilahrs.pc @ONLY)
install(FILES ${CMAKE_CURRENT_BINARY_DIR}/ilahrs.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)
# MIT OR Apache-2.0, at the user's option: both texts go with the library.
install(FILES LICENSE-MIT LICENSE-APACHE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/ilahrs)
