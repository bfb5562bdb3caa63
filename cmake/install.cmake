# Install rules and the Debian package. Layout under the prefix:
#   bin/                               every program, sph_load included
#   share/gaze-adaptive-sph/scenes/    the shipped scenes and their gaze recordings (found by the
#                                      programs relative to their own bin/, see scene_loader.cpp)
#   share/gaze-adaptive-sph/proto/     sph.proto, the wire format
#   share/gaze-adaptive-sph/python/    the Python client (sph_client), its generated sph_pb2.py, sph_load.py
#   share/doc/gaze-adaptive-sph/       README, docs/, systemd unit examples
# The build carries no -march: one package runs on any x86-64 (the AVX-512 forms are chosen at run time).

set(SPH_PROGRAMS sph_server sph_bench sph_validate sph_gaze_record sph_keygen sph_relay gaze_bridge)
if(TARGET sph_viewer)
  list(APPEND SPH_PROGRAMS sph_viewer)
endif()
install(TARGETS ${SPH_PROGRAMS} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

install(DIRECTORY ${PROJECT_SOURCE_DIR}/scenes/ DESTINATION ${SPH_INSTALL_SCENEDIR})
install(FILES ${PROJECT_SOURCE_DIR}/proto/sph.proto DESTINATION ${SPH_INSTALL_DATADIR}/proto)

set(SPH_PYTHON_DEST ${SPH_INSTALL_DATADIR}/python)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/clients/python/sph_client DESTINATION ${SPH_PYTHON_DEST}
        PATTERN "__pycache__" EXCLUDE)
install(FILES ${PROJECT_SOURCE_DIR}/clients/python/sph_load.py ${PROJECT_BINARY_DIR}/clients/python/generated/sph_pb2.py DESTINATION ${SPH_PYTHON_DEST})
# The installed sph_load finds its Python files relative to itself, as the programs find the scenes.
set(SPH_LOAD_INSTALLED ${PROJECT_BINARY_DIR}/install/sph_load)
file(CONFIGURE OUTPUT ${SPH_LOAD_INSTALLED} @ONLY CONTENT [[#!/bin/sh
# sph_load, installed: the Python client and the generated protobuf module live in ../@SPH_PYTHON_DEST@.
here=$(dirname "$(readlink -f "$0")")
py="$here/../@SPH_PYTHON_DEST@"
SPH_PB2_DIR="$py" exec /usr/bin/python3 "$py/sph_load.py" "$@"
]])
install(PROGRAMS ${SPH_LOAD_INSTALLED} DESTINATION ${CMAKE_INSTALL_BINDIR})

set(SPH_DOC_DEST ${CMAKE_INSTALL_DATADIR}/doc/gaze-adaptive-sph)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${SPH_DOC_DEST})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/docs/ DESTINATION ${SPH_DOC_DEST}/docs PATTERN "*.sh" EXCLUDE)
install(DIRECTORY ${PROJECT_SOURCE_DIR}/packaging/systemd DESTINATION ${SPH_DOC_DEST}/examples)
foreach(readme server/app/README.md gaze_bridge/README.md client_viewer/README.md proto/README.md
        clients/python/README.md)
  get_filename_component(part ${readme} DIRECTORY)
  string(REPLACE "/" "_" part ${part})
  install(FILES ${PROJECT_SOURCE_DIR}/${readme} DESTINATION ${SPH_DOC_DEST}/${part})
endforeach()

# Debian package: `cpack --config build/CPackConfig.cmake` (or `cmake --build build --target package`).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gaze-adaptive-sph)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Gaze-adaptive SPH water simulation server, gaze bridge and viewer")
set(CPACK_PACKAGE_CONTACT "gaze-adaptive-sph maintainers <maintainers@localhost>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# dpkg-shlibdeps names the shared libraries the programs link (libzmq5, libspdlog, libgomp, GLFW, ...);
# the Python client's modules come on top.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-zmq, python3-protobuf, python3-numpy")
include(CPack)
