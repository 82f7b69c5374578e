# What `cmake --install build --prefix P` (and the .deb, cmake/packaging.cmake) puts where:
#   P/bin/slamkit                  the command
#   P/share/slamkit/eval/*.py      its plot scripts, found relative to the binary
#   P/share/doc/slamkit/           README.md, LICENSE, THIRD_PARTY.md, docs/ (the measurement log
#                                  too) and eval/README.md
#                                  (in the tree's layout, so that the pages' links still hold)
#   P/lib/python3/dist-packages/   the Python module (bin/python), where Debian's python3 finds
#                                  it for P = /usr (SLAMKIT_INSTALL_PYTHON_DIR)
# cpack (and `make install`) install what is built, as `cmake --install` does, instead of first
# building every test suite and benchmark (the default): build the slamkit target before.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)
install(TARGETS slamkit RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
if(SLAMKIT_BUILD_PYTHON)
  set(SLAMKIT_INSTALL_PYTHON_DIR lib/python3/dist-packages CACHE STRING
      "Where the Python module is installed, relative to the prefix")
  # OPTIONAL: installed when built (`--target slamkit_python`, or everything).
  install(TARGETS slamkit_python LIBRARY DESTINATION ${SLAMKIT_INSTALL_PYTHON_DIR} OPTIONAL)
endif()
file(GLOB plot_scripts CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/eval/*.py)
install(FILES ${plot_scripts} DESTINATION ${SLAMKIT_INSTALL_EVAL_DIR})
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${PROJECT_SOURCE_DIR}/LICENSE
              ${PROJECT_SOURCE_DIR}/THIRD_PARTY.md
        DESTINATION ${CMAKE_INSTALL_DOCDIR})
file(GLOB doc_pages CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${doc_pages} DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/images ${PROJECT_SOURCE_DIR}/docs/measurement-log
        DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs)
install(FILES ${PROJECT_SOURCE_DIR}/eval/README.md DESTINATION ${CMAKE_INSTALL_DOCDIR}/eval)
