# `cpack --config build/CPackConfig.cmake -G DEB -B build` (or `cpack -G DEB` in build/):
# build/slamkit_VERSION_ARCH.deb of what cmake/install.cmake installs, under /usr, for
# `apt-get install ./slamkit_*.deb` on Debian 12.
set(CPACK_PACKAGE_NAME slamkit)
set(CPACK_PACKAGE_CONTACT "the slamkit authors")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "offline RGB-D SLAM reconstruction and evaluation")
set(CPACK_PACKAGE_DESCRIPTION "slamkit reads a recorded RGB-D sequence in the TUM RGB-D \
layout, estimates the camera trajectory, fuses the frames into a map (PLY), judges trajectories \
against groundtruth (ATE, RPE) and writes a self-contained HTML report of each run.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# The shared libraries slamkit links (OpenCV, Ceres, PCL, yaml-cpp, ISA-L, lodepng, libpng,
# libgomp...) become Depends with the versions this build needs, from dpkg-shlibdeps (dpkg-dev);
# cmake/packaging_check.cmake stops cpack without it rather than make a .deb that declares none.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_SOURCE_DIR}/cmake/packaging_check.cmake)
# Plots run under /usr/bin/python3 with matplotlib; without it slamkit says so and writes the
# metrics all the same. The Python module, when built, needs numpy.
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS python3-matplotlib)
if(SLAMKIT_BUILD_PYTHON)
  set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "python3-matplotlib, python3-numpy")
endif()
include(CPack)
