# `cmake --install build [--prefix P]` and `cpack` (a .deb for Debian 12): the program as
# P/bin/railbench (P/bin/workbench a link to it, the name the checkout's scripts and docs use) and
# its data directory P/share/railbench (profiles/, scenarios/ with the libraries scenes require,
# plots/ with the plotting package), which the installed program finds from its own path
# (workbench/app/main.cpp, defaultRoot) without RAILBENCH_ROOT. docs/install.md describes it.
include(GNUInstallDirs)
set(RB_DATA_DIR ${CMAKE_INSTALL_DATADIR}/railbench)

install(PROGRAMS $<TARGET_FILE:workbench> DESTINATION ${CMAKE_INSTALL_BINDIR} RENAME railbench)
# A relative link, so the installed tree can be moved (or unpacked from the .deb) as a whole.
install(CODE "
  set(bin \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_BINDIR}\")
  file(REMOVE \"\${bin}/workbench\")
  file(CREATE_LINK railbench \"\${bin}/workbench\" SYMBOLIC)
  message(STATUS \"Installing: \${bin}/workbench -> railbench\")")

install(DIRECTORY profiles/ DESTINATION ${RB_DATA_DIR}/profiles)
# Every shipped scene and library: the libraries (vehicles, tracks, turnout, validation.common,
# studies.lib, hard.lib) are what users' scenes require, the scenes are their examples.
install(DIRECTORY scenarios/ DESTINATION ${RB_DATA_DIR}/scenarios PATTERN "__pycache__" EXCLUDE)
install(DIRECTORY plots/railbench DESTINATION ${RB_DATA_DIR}/plots PATTERN "__pycache__" EXCLUDE)
install(PROGRAMS plots/rbplot DESTINATION ${RB_DATA_DIR}/plots)
install(FILES plots/pyproject.toml DESTINATION ${RB_DATA_DIR}/plots)
install(FILES README.md LICENSE NOTICE docs/install.md DESTINATION ${CMAKE_INSTALL_DOCDIR})

# cpack -G DEB (from the build folder): railbench_<version>_<arch>.deb for Debian 12. The shared
# libraries the program links are found by dpkg-shlibdeps (package dpkg-dev); the Python
# packages the plots need are listed here.
set(CPACK_PACKAGE_NAME railbench)
set(CPACK_PACKAGE_VENDOR "railbench")
set(CPACK_PACKAGE_CONTACT "railbench maintainers <railbench@localhost>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
    "Railway vehicle dynamics workbench: Lua scenes, HDF5 results, EN 14363 assessment")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_GENERATOR DEB)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_STRIP_FILES ON)  # the program without its symbol table: a third of its size
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-numpy, python3-matplotlib, python3-h5py")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
include(CPack)
