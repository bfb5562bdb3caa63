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

# What Debian's policy asks of every package (lintian checks it, tests/install/package_test.sh):
# the copyright file, the changelog compressed with gzip -9n (no name, no time: reproducible), and a
# manual page per program, made from its --help by help2man where the build machine has it.
install(FILES ${PROJECT_SOURCE_DIR}/packaging/debian/copyright DESTINATION ${SPH_DOC_DEST})
find_program(GZIP gzip REQUIRED)
set(SPH_CHANGELOG_GZ ${PROJECT_BINARY_DIR}/packaging/changelog.gz)
add_custom_command(
  OUTPUT ${SPH_CHANGELOG_GZ}
  COMMAND ${CMAKE_COMMAND} -E make_directory ${PROJECT_BINARY_DIR}/packaging
  COMMAND ${GZIP} -9n -c ${PROJECT_SOURCE_DIR}/packaging/debian/changelog > ${SPH_CHANGELOG_GZ}
  DEPENDS ${PROJECT_SOURCE_DIR}/packaging/debian/changelog
  VERBATIM)
set(SPH_PACKAGE_FILES ${SPH_CHANGELOG_GZ})
find_program(HELP2MAN help2man)
if(HELP2MAN)
  set(SPH_MAN_DIR ${PROJECT_BINARY_DIR}/packaging/man)
  set(sph_server_what "gaze-adaptive SPH water simulation server")
  set(sph_bench_what "run SPH scenes headless and report their measurements")
  set(sph_validate_what "check the fluid presets against experiment")
  set(sph_gaze_record_what "remake the shipped gaze recordings")
  set(sph_keygen_what "make CURVE key pairs for sph_server and its clients")
  set(sph_relay_what "forward one sph_server's frames to many viewers")
  set(gaze_bridge_what "stream an eye tracker's gaze to sph_server")
  set(sph_viewer_what "draw the water of an sph_server and send its camera")
  set(sph_load_what "load generator for sph_server")
  foreach(program ${SPH_PROGRAMS} sph_load)
    if(program STREQUAL "sph_load")
      set(command ${CMAKE_RUNTIME_OUTPUT_DIRECTORY}/sph_load)  # the build tree's wrapper (clients/python)
      set(depends sph_client_python)
    else()
      set(command $<TARGET_FILE:${program}>)
      set(depends ${program})
    endif()
    add_custom_command(
      OUTPUT ${SPH_MAN_DIR}/${program}.1.gz
      COMMAND ${CMAKE_COMMAND} -E make_directory ${SPH_MAN_DIR}
      COMMAND ${HELP2MAN} --no-info --no-discard-stderr --name=${${program}_what} --output=${SPH_MAN_DIR}/${program}.1
              ${command}
      COMMAND ${GZIP} -9nf ${SPH_MAN_DIR}/${program}.1
      DEPENDS ${depends}
      VERBATIM)
    list(APPEND SPH_PACKAGE_FILES ${SPH_MAN_DIR}/${program}.1.gz)
    install(FILES ${SPH_MAN_DIR}/${program}.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  endforeach()
else()
  message(STATUS "help2man not found: no manual pages (bash scripts/install_deps.sh installs it)")
endif()
add_custom_target(sph_package_files ALL DEPENDS ${SPH_PACKAGE_FILES})
install(FILES ${SPH_CHANGELOG_GZ} DESTINATION ${SPH_DOC_DEST})

# Debian package: `cpack --config build/CPackConfig.cmake` (or `cmake --build build --target package`).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME gaze-adaptive-sph)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Gaze-adaptive SPH water simulation server, gaze bridge and viewer")
# The extended description (the summary above is the synopsis), lines of at most 72 characters.
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "A water simulation that puts its detail where the user looks.
sph_server steps an adaptive smoothed particle hydrodynamics (SPH)
simulation on the CPU and streams particle frames over ZeroMQ;
gaze_bridge reads an eye tracker (Pupil Capture, Gazepoint) and tells
the server where the user looks; sph_viewer draws the water and sends
its camera. sph_bench and sph_validate measure the methods and check
the physics against experiment; sph_relay, sph_keygen and sph_load
serve remote viewers, CURVE keys and load tests.")
# A placeholder address: replace it with the maintainers' real one before publishing the package.
set(CPACK_PACKAGE_CONTACT "gaze-adaptive-sph maintainers <sph-maintainers@example.org>")
set(CPACK_STRIP_FILES ON)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
# dpkg-shlibdeps names the shared libraries the programs link (libzmq5, libspdlog, libgomp, GLFW, ...);
# the Python client's modules come on top.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "python3, python3-zmq, python3-protobuf, python3-numpy")
include(CPack)
