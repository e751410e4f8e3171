#!/usr/bin/env bash
# Installs the Debian 12 packages Proxima needs to build and test (README.md lists what each is
# for). Idempotent: when every package is already installed it changes nothing and needs no
# network; otherwise it runs `apt-get update` and then installs what is missing
# (PROXIMA_REINSTALL_DEPENDENCIES=1 passes every package to apt-get regardless). Runs without a
# terminal (CI=true, no standard input). Needs root, or sudo for a normal user.
set -euo pipefail

packages=(
  # toolchain
  cmake ninja-build g++ pkg-config git ccache
  # mesh readers, the haptic pipeline and its rendering
  libvtk9-dev
  # the applications' Qt windows: VTK's Qt widget, with Qt 5 (qtbase5-dev) and QTest
  libvtk9-qt-dev
  # the viewer's check for a display before VTK opens its X window
  libx11-dev
  # OFF files and mesh preparation
  libopenmesh-dev
  # exact oracles in tests, AABB-tree baseline in benchmarks
  libcgal-dev
  # texture images; the tools are needed by find_package(OpenImageIO)
  libopenimageio-dev openimageio-tools
  # command line and reports
  libcli11-dev nlohmann-json3-dev
  # devices: SpaceMouse (hidapi), Falcon (libusb); umockdev fakes their nodes in the tests
  libhidapi-dev libusb-1.0-0-dev umockdev libumockdev-dev
  # tests, benchmarks, offscreen rendering and plots
  libgtest-dev libgmock-dev libbenchmark-dev xvfb xauth python3-matplotlib
  # the window tests: real X mouse and key events sent to proxima view under Xvfb
  xdotool
  # libFuzzer targets (Tools/fuzz-smoke.sh): clang with its fuzzer and sanitizer runtimes
  clang-14 libclang-rt-14-dev
  # the format check of CI (Tools/check-format.sh, .clang-format)
  clang-format-14
  # the API reference (the docs target, Documentation/Doxyfile.in)
  doxygen
  # the haptic server (Library/Net): gRPC, protobuf and their compilers; the Python client's
  # runtime (proxima.haptic_client, generated from the same .proto)
  libgrpc++-dev libprotobuf-dev protobuf-compiler protobuf-compiler-grpc python3-grpcio
  python3-protobuf
  # the TLS test of the server makes a self-signed certificate
  openssl
  # rigid bodies and mechanisms (Library/Dynamics)
  libmujoco-dev
  # the Python module (pybind11), the vtkHaptic* classes in VTK's Python, its tests (pytest)
  # and batch runs on a Dask cluster
  pybind11-dev python3-dev python3-numpy python3-vtk9 python3-pytest python3-distributed
)

missing=()
for package in "${packages[@]}"; do
  if [ "${PROXIMA_REINSTALL_DEPENDENCIES:-0}" = 1 ] || ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q 'install ok installed'; then
    missing+=("$package")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "install-dependencies: all ${#packages[@]} Debian packages are installed"
  exit 0
fi

as_root=()
if [ "$(id -u)" -ne 0 ]; then
  if ! command -v sudo > /dev/null; then
    echo "install-dependencies: missing ${missing[*]}; run this as root" >&2
    exit 1
  fi
  as_root=(sudo)
fi

echo "install-dependencies: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
"${as_root[@]}" apt-get update -q < /dev/null
# VTK alone pulls in several hundred packages: allow a few minutes.
"${as_root[@]}" apt-get install -y -q --no-install-recommends -o Dpkg::Use-Pty=0 "${missing[@]}" < /dev/null
