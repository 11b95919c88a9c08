# Fails, naming a tool that the test command installs (cmake/debian-packages.txt) but that
# configure did not find, so that a missing tool fails the suite instead of skipping its tests.
#   -DTOOL=NAME -DPACKAGE=DEBIAN_PACKAGE
message(FATAL_ERROR "${TOOL} was not found when towgeom was configured, so this test cannot run: "
  "install ${PACKAGE} (bash cmake/ensure_packages.sh installs every package the tests need), then "
  "reconfigure (bash cmake/build.sh ...)")
