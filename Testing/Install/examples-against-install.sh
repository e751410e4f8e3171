#!/usr/bin/env bash
# Install.ExamplesAgainstInstall (issue 19): `cmake --install` this build into a prefix, move the
# prefix elsewhere (an installation must not remember where it was made), check that it carries
# the licence and the shipped data's credits (LICENSE and NOTICE in its documentation folder, as
# the source has them), configure Examples/ against it with find_package(Proxima), build them, and
# run them:
#   - probe_mesh on the shared screw and its probe path (an STL icosphere and the bundled
#     press-and-stroke path without the shared data), read through the VTK readers' module, against the installed `proxima run` on the same files: the proxy and
#     force columns must be the same numbers, and the module must be the installed one;
#   - the API reference (api/ in the same folder) when the build made one;
#   - kernel_only (the kernel alone), also built with nothing but pkg-config's flags;
#   - haptic_pipeline (the VTK pipeline with the threaded runtime), which checks its own answer;
#   - the examples' own ctest suite (the exported scripted-path harness and oracle);
#   - probe_mesh.py, the same program in Python on the installed package proxima, against the
#     same trace, with the same check of where the module came from, and proxima.vtk on a
#     vtkPolyData made in Python (when the build made Python).
# Usage: examples-against-install.sh BUILD_DIR SOURCE_DIR [COMPILER_AND_LINKER_FLAGS]
set -euo pipefail
build="$1"
source="$2"
flags="${3:-}"
work="$build/install-check"
rm -rf "$work"
mkdir -p "$work"

cmake --install "$build" --prefix "$work/made-here" > "$work/install.log"
mv "$work/made-here" "$work/prefix"
prefix="$work/prefix"

# A binary distribution must carry the licence's text, and the CC BY meshes their credits, in the
# build's documentation folder (share/doc/proxima unless CMAKE_INSTALL_DOCDIR moved it).
docdir="$(sed -n 's/^CMAKE_INSTALL_DOCDIR:PATH=//p' "$build/CMakeCache.txt")"
for file in LICENSE NOTICE; do
  if ! cmp -s "$source/$file" "$prefix/${docdir:-share/doc/proxima}/$file"; then
    echo "the installation has no ${docdir:-share/doc/proxima}/$file equal to the source's $file" >&2
    exit 1
  fi
done
# The API reference goes with the installation when the build made it (PROXIMA_BUILD_DOCS).
if grep -q '^PROXIMA_BUILD_DOCS:BOOL=ON' "$build/CMakeCache.txt" &&
  ! grep -q 'ProxySolver' "$prefix/${docdir:-share/doc/proxima}/api/classproxima_1_1ProxySolver.html"; then
  echo "the installation has no API reference in ${docdir:-share/doc/proxima}/api" >&2
  exit 1
fi

cmake -G Ninja -S "$source/Examples" -B "$work/examples" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags" \
  > "$work/configure.log"
cmake --build "$work/examples" --parallel 2 > "$work/build.log"

# The shared screw (an STL scan of a real part) and its person-like probe path when the shared
# data is there (PROXIMA_TEST_DATA, the build's test-data folder, links to it), else an STL
# icosphere and the bundled path.
shared="${PROXIMA_TEST_DATA:-}"
if [ -n "$shared" ] && [ -f "$shared/meshes/M3x10_screw.stl" ]; then
  mesh="$shared/meshes/M3x10_screw.stl"
  path="$shared/paths/screw-probe.csv"
  scale=0.005
  radius=0.0005
else
  mesh="$work/icosphere.stl"
  path="$source/Data/Paths/icosphere-4-press-stroke.csv"
  scale=1
  radius=0.001
  "$prefix/bin/proxima" generate icosphere --subdivisions 4 --radius 0.05 --out "$mesh" > /dev/null
fi
"$prefix/bin/proxima" run --mesh "$mesh" --scale "$scale" --path "$path" --radius "$radius" \
  --out "$work/proxima-run.csv" > /dev/null
LD_DEBUG=files "$work/examples/probe_mesh" "$mesh" "$scale" "$radius" "$path" \
  > "$work/probe_mesh.csv" 2> "$work/probe_mesh.log"

# The mesh readers' module must come from the moved installation: `log` is LD_DEBUG's.
check_module_location() {
  local program="$1" log="$2" loaded
  loaded="$(grep -o '/[^[:space:]]*proxima-vtk-mesh-readers\.so' "$log" | head -n 1 || true)"
  case "$loaded" in
    "$prefix"/lib/proxima/*) ;;
    *)
      echo "$program loaded the mesh readers' module from '${loaded:-nowhere}', not from $prefix" >&2
      exit 1
      ;;
  esac
}

# Every tick of `example` must hold proxima run's proxy and force.
compare_with_run() {
  /usr/bin/python3 - "$work/proxima-run.csv" "$1" "$2" <<'PYTHON'
import csv
import sys


def rows(name, columns):
    with open(name) as f:
        reader = csv.DictReader(line for line in f if not line.startswith("#"))
        return [[float(row[c]) for c in columns] for row in reader]


columns = ["proxy_x", "proxy_y", "proxy_z", "force_x", "force_y", "force_z"]
trace = rows(sys.argv[1], columns)
example = rows(sys.argv[2], columns)
if len(trace) != len(example):
    sys.exit(f"proxima run wrote {len(trace)} ticks, {sys.argv[3]} {len(example)}")
for tick, (a, b) in enumerate(zip(trace, example)):
    if a != b:
        sys.exit(f"tick {tick}: proxima run {a}, {sys.argv[3]} {b}")
pressed = sum(1 for row in example if row[3] ** 2 + row[4] ** 2 + row[5] ** 2 > 0.25)
if pressed < 100:
    sys.exit(f"only {pressed} ticks pressed the sphere: the comparison says little")
print(f"{sys.argv[3]}: {len(example)} ticks, the same as proxima run's trace ({pressed} pressing)")
PYTHON
}
check_module_location probe_mesh "$work/probe_mesh.log"
compare_with_run "$work/probe_mesh.csv" probe_mesh

"$work/examples/kernel_only"
# The kernel without CMake: pkg-config's flags alone.
PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --exists proxima-kernel
# shellcheck disable=SC2046 # the flags are words
g++ $flags -O2 "$source/Examples/kernel_only.cpp" -o "$work/kernel_only_pkg_config" \
  $(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags --libs proxima-kernel)
"$work/kernel_only_pkg_config"
"$work/examples/haptic_pipeline"
ctest --test-dir "$work/examples" --output-on-failure

# Python, when this build made the module: the package found by PYTHONPATH alone.
package="$prefix/lib/python3/dist-packages"
if [ -d "$package/proxima" ]; then
  PYTHONPATH="$package" LD_DEBUG=files /usr/bin/python3 "$source/Examples/probe_mesh.py" \
    "$mesh" "$scale" "$radius" "$path" > "$work/probe_mesh_py.csv" 2> "$work/probe_mesh_py.log"
  check_module_location probe_mesh.py "$work/probe_mesh_py.log"
  compare_with_run "$work/probe_mesh_py.csv" probe_mesh.py
  # The vtkHaptic* classes in VTK's Python, from the moved installation's own library.
  if [ -f "$package/proxima/vtk.py" ]; then
    PYTHONPATH="$package" LD_DEBUG=files /usr/bin/python3 - 2> "$work/vtk_py.log" <<'PYTHON'
from vtkmodules.vtkFiltersSources import vtkSphereSource
from proxima.vtk import vtkHapticScene
sphere = vtkSphereSource()
sphere.Update()
scene = vtkHapticScene()
scene.AddObject(sphere.GetOutput())
scene.Update()
assert scene.GetNumberOfObjects() == 1 and scene.GetSceneVersion() == 1
print("proxima.vtk: a vtkPolyData made in Python became a haptic scene")
PYTHON
    loaded="$(grep -o '/[^[:space:]]*vtkProximaHaptic[^[:space:]]*\.so' "$work/vtk_py.log" | head -n 1 || true)"
    case "$loaded" in
      "$prefix"/lib/*) ;;
      *)
        echo "proxima.vtk loaded vtkProximaHaptic from '${loaded:-nowhere}', not from $prefix" >&2
        exit 1
        ;;
    esac
  fi
fi
echo "examples built and run against the installation in $prefix"
