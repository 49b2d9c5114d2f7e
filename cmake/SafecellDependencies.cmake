# Third-party packages of the coprocessor (Debian's -dev packages; .ci/install-deps installs them).
# Found at the top level so the tests see the same imported targets.
find_package(yaml-cpp REQUIRED)
find_package(CLI11 REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(OpenCV 4 REQUIRED COMPONENTS core imgproc imgcodecs calib3d videoio)
find_package(urdfdom REQUIRED)
find_package(tinyxml2 REQUIRED)  # the URDF gate: depth-limited, before urdfdom's TinyXML 1
find_package(assimp REQUIRED)
find_package(fcl REQUIRED)
find_package(benchmark REQUIRED)
find_package(Boost 1.74 REQUIRED)  # Boost.Asio (header-only) for the link
find_package(Threads REQUIRED)
