# Third-party packages of the coprocessor (Debian's -dev packages; .ci/install-deps installs them).
# Found at the top level so the tests see the same imported targets.
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
