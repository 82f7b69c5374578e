# Read by cpack before it packs (CPACK_PROJECT_CONFIG_FILE, cmake/packaging.cmake). Without
# dpkg-shlibdeps CPack only prints a line and makes a .deb that declares no library at all: it
# installs anywhere and then cannot start. Refuse instead.
if(CPACK_GENERATOR STREQUAL "DEB")
  find_program(dpkg_shlibdeps dpkg-shlibdeps)
  if(NOT dpkg_shlibdeps)
    message(FATAL_ERROR "cpack -G DEB needs dpkg-shlibdeps to declare the libraries slamkit "
                        "links: apt-get install dpkg-dev")
  endif()
endif()
